#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (idempotent), builds Prism and runs the main job:
# renders the shader gallery headlessly (EGL surfaceless on Mesa llvmpipe) into gallery/
# (one PNG per shader, variant and mesh, plus the contact sheet gallery/gallery.png), and every
# example scene of examples/scenes/ (the diffraction scenes among them) into gallery/scenes/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=${BUILD_DIR:-build}
OUT_DIR=${1:-gallery}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_RUNTIME=ON
cmake --build "$BUILD_DIR" -j "$(nproc)" --target prism-gallery prism-render
"$BUILD_DIR"/apps/prism-gallery --out "$OUT_DIR"
mkdir -p "$OUT_DIR/scenes"
for scene in examples/scenes/*.json; do
  "$BUILD_DIR"/apps/prism-render --scene "$scene" --out "$OUT_DIR/scenes/$(basename "$scene" .json).png"
done
echo "scenes written to $OUT_DIR/scenes/"
echo "gallery written to $OUT_DIR/gallery.png"
