#!/usr/bin/env bash
# Integration test of hot reload from an outside project (issue 22, item 3): installs this
# Prism build into a prefix, builds examples/consumer against that prefix alone
# (find_package(Prism), Ninja, the prism_consumer_reload target only), and runs it: it
# starts reloading its lit_shaders catalogue from the lit_shaders_sources.hpp that
# prism_add_shaders() wrote, edits the material.glsl of the install prefix, and checks
# that the next frame draws with the rebuilt program. Also checks that the catalogue's
# generated files name no absolute path, and that the source record names the prefix.
#
# Usage: installed_reload.sh --source <prism source> --build <prism build> --work <scratch dir>
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
    *) echo "installed_reload.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$SOURCE" ] || [ -z "$BUILD" ] || [ -z "$WORK" ]; then
  echo "usage: installed_reload.sh --source <prism source> --build <prism build> --work <scratch dir>" >&2
  exit 2
fi
unset MAKEFLAGS MFLAGS MAKELEVEL DESTDIR CMAKE_GENERATOR CMAKE_BUILD_PARALLEL_LEVEL
rm -rf "$WORK" && mkdir -p "$WORK"
PREFIX=$WORK/prefix
FAILURES=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; FAILURES=$((FAILURES + 1)); }
show_log() { echo "  --- last lines of $1:"; tail -n 25 "$1" | sed 's/^/  | /'; }

if ! "$CMAKE" --install "$BUILD" --prefix "$PREFIX" >"$WORK/install.log" 2>&1; then
  fail "cmake --install the Prism build"; show_log "$WORK/install.log"; exit 1
fi
pass "cmake --install the Prism build into $PREFIX"
MATERIAL=$PREFIX/share/prism/modules/material.glsl
[ -f "$MATERIAL" ] || { fail "the prefix has no $MATERIAL"; exit 1; }

src=$WORK/consumer bld=$WORK/build
cp -r "$SOURCE/examples/consumer" "$src"
if ! "$CMAKE" -S "$src" -B "$bld" -G Ninja -DCMAKE_PREFIX_PATH="$PREFIX" -DCMAKE_BUILD_TYPE=Release \
     >"$WORK/configure.log" 2>&1; then
  fail "configure the consumer against the prefix"; show_log "$WORK/configure.log"; exit 1
fi
if ! "$CMAKE" --build "$bld" --parallel "$JOBS" --target prism_consumer_reload >"$WORK/build.log" 2>&1; then
  fail "build prism_consumer_reload against the prefix"; show_log "$WORK/build.log"; exit 1
fi
pass "build prism_consumer_reload against the prefix"

gen=$bld/lit_shaders_generated/consumer
if grep -q -F -e "$WORK" "$gen/lit_shaders.hpp" "$gen/lit_shaders.cpp"; then
  fail "the catalogue's generated files name an absolute path"
else
  pass "the catalogue's generated files name no absolute path"
fi
if grep -q -F "$PREFIX/share/prism/modules" "$gen/lit_shaders_sources.hpp" &&
   grep -q -F "\"material.glsl\", 1}" "$gen/lit_shaders.cpp"; then
  pass "lit_shaders_sources.hpp names the prefix's modules; the catalogue finds material.glsl in -I 1"
else
  fail "the source record of lit_shaders"; sed 's/^/  | /' "$gen/lit_shaders_sources.hpp"
fi

if "$bld/prism_consumer_reload" "$MATERIAL" >"$WORK/run.log" 2>&1 && grep -qx "reload of an installed module: OK" "$WORK/run.log"; then
  pass "an edit of the prefix's material.glsl is in the next frame ($(head -n 1 "$WORK/run.log"))"
else
  fail "prism_consumer_reload: an edit of the prefix's material.glsl"; show_log "$WORK/run.log"
fi
echo "installed_reload: $FAILURES failed check(s)"
[ "$FAILURES" -eq 0 ]
