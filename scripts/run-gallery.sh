#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (idempotent), builds Prism and runs the main job:
# renders every system headlessly (EGL surfaceless on Mesa llvmpipe) into gallery/ and
# writes the report gallery/index.html (scripts/render_gallery.py):
#   the classic catalogue on its meshes (gallery/*.png, contact sheet gallery/gallery.png),
#   every examples/scenes/*.json (gallery/scenes/), the blue-noise samplers at 1 spp and
#   accumulated (gallery/bluenoise/), 8-frame rain and water sequences as strips
#   (gallery/rain-sequence/, gallery/water-sequence/), and the benches' trade plots
#   (gallery/plots/). One progress line per image; the last line names the page to open.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=${BUILD_DIR:-build}
OUT_DIR=${1:-gallery}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_BUILD_RUNTIME=ON -DPRISM_BUILD_EXAMPLES=ON
cmake --build "$BUILD_DIR" -j "$(nproc)" --target prism-gallery prism-render prism-bluenoise prism-rain water prism-agreement
python3 scripts/render_gallery.py --build-dir "$BUILD_DIR" --out "$OUT_DIR"
