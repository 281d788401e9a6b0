#!/usr/bin/env bash
# Integration test of the installed runtime: packages this Prism build (runtime included)
# as the Debian package prism-dev with cpack, which lintian must pass without an error,
# and unpacks it with dpkg-deb -x into a scratch root (issue 29, item 3; nothing is
# installed on the machine); its usr/ is the prefix the rest uses. Then builds examples/consumer against that prefix alone with Ninja and
# with Unix Makefiles (find_package(Prism)), runs its prism_consumer_render, and compares
# the PNG with tests/golden/consumer/tinted_phong.png (thresholds in render_png.cpp).
# Also checks that the prefix holds the runtime's headers, libraries, generated
# catalogues and glad headers, and no path of the source tree leaks into the build; and
# the safe defaults of prism_add_shaders() (issue 22, item 4): a catalogue with no
# NAMESPACE links beside Prism's own into one program (prism_consumer_two_catalogues),
# its lygia-style uniforms build without a word, and with no CONTRACT a misspelled
# a_positon is a GCC-style warning at toon.vert with "did you mean"; and hot reload from the
# outside project (issue 22, item 3): prism_consumer_reload watches its lit_shaders
# catalogue through the lit_shaders_sources.hpp that prism_add_shaders() wrote, the test
# edits the prefix's material.glsl under it, and the next frame must use the rebuilt program.
# The pkg-config consumer (issue 29, item 4): examples/consumer/Makefile, built with make and
# the prefix's prism.pc alone, renders the same golden PNG.
#
# Usage: installed_runtime.sh --source <prism source> --build <prism build> --work <scratch dir>
#          [--cmake <cmake>] [--jobs <n>]
set -uo pipefail
SOURCE="" BUILD="" WORK="" CMAKE=cmake JOBS=2
while [ $# -gt 0 ]; do
  case "$1" in
    --source) SOURCE=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --work) WORK=$2; shift 2 ;;
    --cmake) CMAKE=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    *) echo "installed_runtime.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$SOURCE" ] || [ -z "$BUILD" ] || [ -z "$WORK" ]; then
  echo "usage: installed_runtime.sh --source <prism source> --build <prism build> --work <scratch dir>" >&2
  exit 2
fi
unset MAKEFLAGS MFLAGS MAKELEVEL DESTDIR CMAKE_GENERATOR CMAKE_BUILD_PARALLEL_LEVEL
rm -rf "$WORK" && mkdir -p "$WORK"
ROOT=$WORK/deb-root PREFIX=$WORK/deb-root/usr
# The package's library folder: Debian's multiarch one, lib/x86_64-linux-gnu.
LIBDIR=lib/$(dpkg-architecture -qDEB_HOST_MULTIARCH)
FAILURES=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; FAILURES=$((FAILURES + 1)); }
show_log() { echo "  --- last lines of $1:"; tail -n 25 "$1" | sed 's/^/  | /'; }

CPACK=$(dirname "$(command -v "$CMAKE")")/cpack  # beside the cmake that built Prism
if "$CPACK" -G DEB --config "$BUILD/CPackConfig.cmake" -B "$WORK/deb" >"$WORK/cpack.log" 2>&1; then
  pass "cpack -G DEB packages the Prism build"
else
  fail "cpack -G DEB"; show_log "$WORK/cpack.log"; exit 1
fi
DEB=$(find "$WORK/deb" -maxdepth 1 -name 'prism-dev_*_*.deb' -print -quit)
if [ -z "$DEB" ]; then
  fail "no prism-dev_<version>_<arch>.deb in $WORK/deb"; exit 1
fi
depends=$(dpkg-deb -f "$DEB" Depends)
for pkg in glslang-dev libglm-dev libpng-dev nlohmann-json3-dev libtinyobjloader-dev; do
  case ", $depends," in
    *", $pkg,"*) pass "$(basename "$DEB") depends on $pkg" ;;
    *) fail "$(basename "$DEB") does not depend on $pkg (Depends: $depends)" ;;
  esac
done
if lintian --fail-on error "$DEB" >"$WORK/lintian.log" 2>&1; then
  pass "lintian: no error ($(grep -c '^W:' "$WORK/lintian.log") warning(s), in $WORK/lintian.log)"
else
  fail "lintian reports errors"; grep '^E:' "$WORK/lintian.log" | head -n 10
fi
if dpkg-deb -x "$DEB" "$ROOT" && [ -d "$PREFIX" ]; then
  pass "dpkg-deb -x unpacks the package into $ROOT"
else
  fail "dpkg-deb -x $DEB $ROOT"; exit 1
fi
for f in include/prism/gl/program.hpp include/prism/render/gpu_mesh.hpp include/prism/geometry/mesh.hpp \
         include/prism/image/png_io.hpp include/prism/view/camera.hpp include/prism/scene/scene_loader.hpp \
         include/prism/catalog/shader_catalog.hpp include/prism/shaders.hpp include/prism-glad/glad/gl.h \
         "$LIBDIR/libprism_gl.a" "$LIBDIR/libprism_render.a" "$LIBDIR/cmake/Prism/PrismTargets.cmake" \
         bin/prism-shaderc \
         "$LIBDIR/pkgconfig/prism.pc"; do
  if [ -e "$PREFIX/$f" ]; then pass "prefix has $f"; else fail "prefix lacks $f"; fi
done
# Libraries in Debian's multiarch folder, none in lib/ itself (Debian policy, lintian).
stray=$(find "$PREFIX/lib" -maxdepth 1 -type f -print -quit)
if [ -z "$stray" ] && [ "$LIBDIR" != lib/ ]; then
  pass "libraries under $LIBDIR, none in lib/"
else
  fail "libraries in lib/ ($stray), not under $LIBDIR"
fi
# Glad's headers stay out of include/, where they would shadow a consumer's own glad.
if [ -e "$PREFIX/include/glad" ] || [ -e "$PREFIX/include/KHR" ]; then
  fail "prefix has include/glad or include/KHR (glad's headers belong in include/prism-glad)"
else
  pass "prefix has no include/glad or include/KHR"
fi

# check_pkg_config: examples/consumer/Makefile with pkg-config and the prefix alone.
check_pkg_config() {
  local src=$WORK/pkg-config/consumer bld=$WORK/pkg-config/build
  mkdir -p "$WORK/pkg-config" && cp -r "$SOURCE/examples/consumer" "$src"
  if PKG_CONFIG_PATH=$PREFIX/$LIBDIR/pkgconfig make -C "$src" BUILD="$bld" CXXFLAGS=-O1 \
       >"$WORK/pkg-config/build.log" 2>&1; then
    pass "pkg-config: make builds the consumer's renderer with prism.pc"
  else
    fail "pkg-config: make with prism.pc"; show_log "$WORK/pkg-config/build.log"; return
  fi
  if "$bld/prism_consumer_render" "$WORK/pkg-config/tinted_phong.png" \
       --golden "$SOURCE/tests/golden/consumer/tinted_phong.png" >"$WORK/pkg-config/run.log" 2>&1; then
    pass "pkg-config: rendered PNG matches the golden ($(grep golden "$WORK/pkg-config/run.log"))"
  else
    fail "pkg-config: prism_consumer_render against the golden"; show_log "$WORK/pkg-config/run.log"
  fi
}
check_pkg_config

# check_safe_defaults <generator> <consumer copy> <build dir> <log dir>
check_safe_defaults() {
  local gen=$1 src=$2 bld=$3 logs=$4
  if "$bld/prism_consumer_two_catalogues" >"$logs/two.log" 2>&1 && grep -qx "two catalogues: OK" "$logs/two.log"; then
    pass "$gen: toon_shaders (no NAMESPACE) and prism::shaders in one program ($(head -n 1 "$logs/two.log"))"
  else
    fail "$gen: prism_consumer_two_catalogues"; show_log "$logs/two.log"
  fi
  if grep -q "toon\.[a-z]*:[0-9]*:[0-9]*: \(warning\|error\)" "$logs/build.log"; then
    fail "$gen: toon's own uniforms (u_resolution, u_time) drew a diagnostic"; show_log "$logs/build.log"
  else
    pass "$gen: toon's own uniforms (u_resolution, u_time) build without a diagnostic"
  fi
  sed -i 's/a_position/a_positon/g' "$src/shaders/toon/toon.vert"
  local line; line=$(grep -n "^in vec3 a_positon;" "$src/shaders/toon/toon.vert" | cut -d: -f1)
  "$CMAKE" --build "$bld" --parallel "$JOBS" --target toon_shaders >"$logs/misspelt.log" 2>&1
  local want="shaders/toon/toon\.vert:$line:[0-9]*: warning: vertex attribute 'a_positon' .*(did you mean 'a_position'?)"
  if grep -q "$want" "$logs/misspelt.log"; then
    pass "$gen: no CONTRACT: a_positon is a warning at toon.vert:$line with did you mean"
  else
    fail "$gen: no CONTRACT: a_positon warning at toon.vert:$line"; show_log "$logs/misspelt.log"
  fi
}

# check_reload <generator> <build dir> <log dir>: the catalogue's generated files name no
# absolute path, its source record names the prefix's modules, and an edit of the
# prefix's material.glsl (restored afterwards) is in the next frame.
check_reload() {
  local gen=$1 bld=$2 logs=$3 material=$PREFIX/share/prism/modules/material.glsl
  local generated=$bld/lit_shaders_generated/consumer
  if grep -q -F -e "$WORK" "$generated/lit_shaders.hpp" "$generated/lit_shaders.cpp"; then
    fail "$gen: the catalogue's generated files name an absolute path"
  elif grep -q -F "$PREFIX/share/prism/modules" "$generated/lit_shaders_sources.hpp" &&
       grep -q -F '"material.glsl", 1}' "$generated/lit_shaders.cpp"; then
    pass "$gen: lit_shaders_sources.hpp names the prefix's modules; the catalogue, no absolute path"
  else
    fail "$gen: the source record of lit_shaders"; show_log "$generated/lit_shaders_sources.hpp"
  fi
  cp "$material" "$logs/material.glsl.orig"
  if "$bld/prism_consumer_reload" "$material" >"$logs/reload.log" 2>&1 &&
     grep -qx "reload of an installed module: OK" "$logs/reload.log"; then
    pass "$gen: an edit of the prefix's material.glsl is in the next frame ($(head -n 1 "$logs/reload.log"))"
  else
    fail "$gen: prism_consumer_reload: an edit of the prefix's material.glsl"; show_log "$logs/reload.log"
  fi
  cp "$logs/material.glsl.orig" "$material"
}

for gen in Ninja "Unix Makefiles"; do
  tag=${gen// /-}
  src=$WORK/$tag/consumer bld=$WORK/$tag/build
  mkdir -p "$WORK/$tag" && cp -r "$SOURCE/examples/consumer" "$src"
  if ! "$CMAKE" -S "$src" -B "$bld" -G "$gen" -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_BUILD_TYPE=Release \
       >"$WORK/$tag/configure.log" 2>&1; then
    fail "$gen: configure the consumer against the prefix"; show_log "$WORK/$tag/configure.log"; continue
  fi
  pass "$gen: configure the consumer against the prefix"
  if grep -q -F "$SOURCE/runtime" "$bld/CMakeCache.txt"; then
    fail "$gen: the consumer's cache names Prism's source tree"
  else
    pass "$gen: nothing of Prism's source tree in the consumer's cache"
  fi
  if ! "$CMAKE" --build "$bld" --parallel "$JOBS" >"$WORK/$tag/build.log" 2>&1; then
    fail "$gen: build the consumer with the installed runtime"; show_log "$WORK/$tag/build.log"; continue
  fi
  pass "$gen: build the consumer with the installed runtime"
  if "$bld/prism_consumer_render" "$WORK/$tag/tinted_phong.png" --golden "$SOURCE/tests/golden/consumer/tinted_phong.png" \
       >"$WORK/$tag/run.log" 2>&1; then
    pass "$gen: rendered PNG matches the golden ($(grep golden "$WORK/$tag/run.log"))"
  else
    fail "$gen: prism_consumer_render against the golden"; show_log "$WORK/$tag/run.log"
  fi
  check_safe_defaults "$gen" "$src" "$bld" "$WORK/$tag"
  check_reload "$gen" "$bld" "$WORK/$tag"
done
echo "installed_runtime: $FAILURES failed check(s)"
[ "$FAILURES" -eq 0 ]
