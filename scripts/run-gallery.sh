#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (idempotent), builds Prism and runs the main job:
# renders the shader gallery headlessly (EGL surfaceless on Mesa llvmpipe) into gallery/
# (one PNG per shader, variant and mesh, plus the contact sheet gallery/gallery.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=${BUILD_DIR:-build}
OUT_DIR=${1:-gallery}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_RUNTIME=ON
cmake --build "$BUILD_DIR" -j "$(nproc)" --target prism-gallery
"$BUILD_DIR"/apps/prism-gallery --out "$OUT_DIR"
echo "gallery written to $OUT_DIR/gallery.png"
