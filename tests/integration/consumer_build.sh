#!/usr/bin/env bash
# Integration test of Prism's CMake step: builds examples/consumer (a standalone project
# with two prism_add_shaders() catalogues) against this source tree with FetchContent
# (SOURCE_DIR, no network) under Ninja, Prism's runtime off, and under Unix Makefiles
# against an install of this build (find_package; it compiles no second prism-shaderc,
# which would cost CI a minute), and checks that Prism is a lean subproject (issue 29):
# the Ninja build's `cmake --install` holds nothing of Prism's, and a configure with Prism's defaults (runtime on), whose
# build graph is read but not built, has at most MAX_LEAN_STEPS steps for a consumer that
# links Prism::render, no Prism program, no object of a system it does not link (rain,
# water, diffraction, blue noise, scene), no install rule of Prism's, and the tool's code
# at -Og (PRISM_SHADERC_OPT_FLAGS) while the runtime keeps the build type's; and that
# `cmake --preset install` has at most MAX_INSTALL_STEPS steps, all of them for what installs,
# prism_web.js included. Both builds copy Prism_WEB_RUNTIME. Both builds check
# the dependency graph through file timestamps:
#   - a rebuild with nothing changed does nothing;
#   - touching tint.glsl (read only by lit_shaders) re-runs prism-shaderc for lit_shaders
#     alone, rewrites no header (content unchanged) and recompiles nothing;
#   - editing tint.glsl rewrites the lit data file (lit_shaders.cpp) only, leaves both
#     headers' mtimes alone, compiles exactly one translation unit (that data file, not
#     main.cpp) and relinks the program;
#   - an include error fails the build with a GCC-style diagnostic at tint.glsl and
#     leaves the previous header intact; fixing it recovers;
#   - a module added to lit's module dir re-runs lit_shaders only;
# then builds the consumer with Ninja and find_package(Prism) against the same install,
# also as a project with an old cmake_minimum_required().
# Works on copies of the consumer under --work; never modifies the source or build tree.
#
# Usage: consumer_build.sh --source <prism source dir> --build <prism build dir> --work <scratch dir>
#          [--cmake <cmake>] [--cxx <compiler>] [--cc <compiler>] [--jobs <n>]
# Prints PASS/FAIL per check; exits 1 when any check failed.
set -uo pipefail

SOURCE="" BUILD="" WORK="" CMAKE=cmake CXX_COMPILER="" C_COMPILER="" JOBS=2
while [ $# -gt 0 ]; do
  case "$1" in
    --source) SOURCE=$2; shift 2 ;;
    --build) BUILD=$2; shift 2 ;;
    --work) WORK=$2; shift 2 ;;
    --cmake) CMAKE=$2; shift 2 ;;
    --cxx) CXX_COMPILER=$2; shift 2 ;;
    --cc) C_COMPILER=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    *) echo "consumer_build.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "$SOURCE" ] || [ -z "$BUILD" ] || [ -z "$WORK" ] || [ ! -f "$SOURCE/examples/consumer/CMakeLists.txt" ]; then
  echo "usage: consumer_build.sh --source <prism source dir> --build <prism build dir> --work <scratch dir>" \
       "[--cmake <cmake>] [--jobs <n>]" >&2
  exit 2
fi
SOURCE=$(cd "$SOURCE" && pwd -P)
mkdir -p "$WORK" && WORK=$(cd "$WORK" && pwd -P)

# The nested builds must not inherit a parent make's jobserver, an install DESTDIR or a
# default generator from the environment.
unset MAKEFLAGS MFLAGS MAKELEVEL DESTDIR CMAKE_GENERATOR CMAKE_BUILD_PARALLEL_LEVEL

# Only the build graph is under test: -O0 without debug info for the consumer's files, and
# prism-shaderc at -Og, Prism's default for a subproject (PRISM_SHADERC_OPT_FLAGS), which
# compiles in less CPU time than -O0 on CI's two cores.
COMMON_ARGS=(-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_C_FLAGS_DEBUG=-O0)
[ -n "$CXX_COMPILER" ] && COMMON_ARGS+=("-DCMAKE_CXX_COMPILER=$CXX_COMPILER")
[ -n "$C_COMPILER" ] && COMMON_ARGS+=("-DCMAKE_C_COMPILER=$C_COMPILER")
# The FetchContent build takes the tool alone.
PRISM_ARGS=(-DPRISM_BUILD_RUNTIME=OFF)
# This build's install, for the find_package builds (install_prism).
PREFIX=$WORK/prefix
# The lean graph has 46 steps (the tool; gl, render and the CPU libraries under them, in
# unity batches, PRISM_UNITY_BUILD; Prism's classic catalogue; the consumer's two
# catalogues and three programs); without Prism's EXCLUDE_FROM_ALL it is 98 (every library
# and catalogue of Prism's).
MAX_LEAN_STEPS=50
MAX_INSTALL_STEPS=100  # issue 37, item 8

FAILURES=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; FAILURES=$((FAILURES + 1)); }
# check <description> <command...>: PASS when the command succeeds.
check() {
  local what=$1; shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}
show_log() {  # the end of a step's log, indented, after a failure
  echo "  --- last lines of $1:"
  tail -n 25 "$1" | sed 's/^/  | /'
}

mtime() { stat -c %.9Y "$1" 2>/dev/null || echo missing; }
same_time() { [ "$1" != missing ] && [ "$1" = "$2" ]; }
later_time() {  # $1 strictly later than $2
  [ "$1" != missing ] && [ "$2" != missing ] && awk -v a="$1" -v b="$2" 'BEGIN { exit !(a > b) }'
}

# Sleep long enough that a file written next gets a later mtime than one written
# before: a few ticks where the file system keeps sub-second times, 1.1 s otherwise.
probe=$WORK/.mtime-probe
touch "$probe"; t1=$(mtime "$probe"); sleep 0.02; touch "$probe"; t2=$(mtime "$probe")
if [ "$t1" != "$t2" ] && [ "${t2#*.}" != 000000000 ]; then TICK=0.05; else TICK=1.1; fi
rm -f "$probe"
tick() { sleep "$TICK"; }

# step <log> <command...>: runs a command with its output in <log>; returns its status.
step() {
  local log=$1; shift
  "$@" >"$log" 2>&1
}

# The same tool run for every build: `cmake --build`, so both generators read alike.
build() { "$CMAKE" --build "$1" --parallel "$JOBS"; }

tool_ran() { grep -q "prism-shaderc: generating" "$1"; }

# Counts the catalogue should report, from the copy's files: one shader per stage-file
# basename; one module per .glsl file directly in the catalogue's module dirs.
count_shaders() { find "$1" -maxdepth 1 -type f \( -name '*.vert' -o -name '*.geom' -o -name '*.frag' -o -name '*.comp' \) \
                    -printf '%f\n' | sed 's/\.[^.]*$//' | sort -u | wc -l; }
count_modules() { find "$@" -maxdepth 1 -type f -name '*.glsl' | wc -l; }

# run_consumer <build dir> <consumer copy> <module dir> <log>: runs the program and
# checks its summary lines against the catalogue's files.
run_consumer() {
  local bld=$1 src=$2 moddir=$3 log=$4 label=$5
  if ! "$bld/prism_consumer" >"$log" 2>&1; then
    fail "$label: prism_consumer runs"; show_log "$log"; return 1
  fi
  local lit_s lit_m plain_s plain_m
  lit_s=$(count_shaders "$src/shaders/lit"); lit_m=$(count_modules "$moddir" "$src/modules/lit")
  plain_s=$(count_shaders "$src/shaders/plain"); plain_m=$(count_modules "$moddir" "$src/modules/plain")
  if grep -qx "lit_shaders: $lit_s shaders, $lit_m modules" "$log" &&
     grep -qx "plain_shaders: $plain_s shaders, $plain_m modules" "$log" &&
     grep -qx "consumer: OK" "$log"; then
    pass "$label: prism_consumer runs and lists $lit_s+$plain_s shaders, $lit_m+$plain_m modules"
  else
    fail "$label: prism_consumer output (expected lit $lit_s/$lit_m, plain $plain_s/$plain_m shaders/modules)"
    show_log "$log"; return 1
  fi
  # Prism_WEB_RUNTIME (FetchContent: the source tree's; find_package: the installed copy).
  check "$label: Prism_WEB_RUNTIME is prism_web.js (the consumer copied it to web/)" \
    cmp -s "$bld/web/prism_web.js" "$SOURCE/scripts/web/prism_web.js"
}

# check_install_preset: the configure line docs/using-prism.md gives for an install
# (`cmake --preset install`) builds only what installs: at most MAX_INSTALL_STEPS steps, no
# program, example, bench or test. Read from the build graph, not built.
check_install_preset() {
  local bld=$WORK/install-preset logs=$WORK/install-preset-logs
  rm -rf "$bld" "$logs"; mkdir -p "$logs"
  if ! step "$logs/configure.log" "$CMAKE" -S "$SOURCE" --preset install -B "$bld"; then
    fail "install preset: configure"; show_log "$logs/configure.log"; return
  fi
  ninja -C "$bld" -t commands all >"$logs/commands.txt" 2>"$logs/commands.err"
  local steps; steps=$(grep -c . "$logs/commands.txt")
  check "install preset: $steps build steps (at most $MAX_INSTALL_STEPS)" \
    test "$steps" -gt 0 -a "$steps" -le "$MAX_INSTALL_STEPS"
  local extra; extra=$(grep -o -E "(^| |$SOURCE/)(apps|examples|bench|tests)/[^ ]*" "$logs/commands.txt" | head -n 3)
  check "install preset: no program, example, bench or test in the graph${extra:+ (has: $extra)}" test -z "$extra"
  check "install preset: installs prism_web.js" grep -q "prism_web.js" "$bld/cmake_install.cmake"
}

# check_generator <tag> <generator> <Prism's module dir> <how> <cmake args for Prism...>:
# the consumer's build with Prism as <how> says (FetchContent or installed) and its
# incremental checks.
check_generator() {
  local tag=$1 gen=$2 moddir=$3 how=$4
  shift 4
  local dir=$WORK/$tag
  local src=$dir/consumer bld=$dir/build logs=$dir/logs
  local started=$SECONDS
  rm -rf "$dir"; mkdir -p "$logs"
  cp -R "$SOURCE/examples/consumer" "$src"
  local tint=$src/modules/lit/tint.glsl
  local lit_stamp=$bld/lit_shaders.stamp plain_stamp=$bld/plain_shaders.stamp
  local lit_hdr=$bld/lit_shaders_generated/consumer/lit_shaders.hpp
  local lit_data=$bld/lit_shaders_generated/consumer/lit_shaders.cpp
  local plain_hdr=$bld/plain_shaders_generated/consumer/plain_shaders.hpp
  local exe=$bld/prism_consumer
  echo "== $gen: $how"
  if ! step "$logs/1-configure.log" "$CMAKE" -S "$src" -B "$bld" -G "$gen" "$@" "${COMMON_ARGS[@]}"; then
    fail "$gen: configure the consumer"; show_log "$logs/1-configure.log"; return
  fi
  pass "$gen: configure the consumer"
  if ! step "$logs/2-build.log" build "$bld"; then
    fail "$gen: build the consumer"; show_log "$logs/2-build.log"; return
  fi
  pass "$gen: build the consumer ($((SECONDS - started)) s)"
  local f missing=0
  for f in "$lit_stamp" "$plain_stamp" "$lit_hdr" "$lit_data" "$plain_hdr" "$exe"; do
    [ -f "$f" ] || { fail "$gen: expected build output $f"; missing=1; }
  done
  [ $missing = 0 ] || return
  run_consumer "$bld" "$src" "$moddir" "$logs/2-run.log" "$gen"
  [ "$tag" = ninja ] && check_consumer_install "$bld" "$logs" "$dir/install"

  # Nothing changed: nothing to do.
  local a_lit a_plain a_lith a_plainh a_exe
  snapshot() { a_lit=$(mtime "$lit_stamp"); a_plain=$(mtime "$plain_stamp"); a_lith=$(mtime "$lit_hdr")
               a_plainh=$(mtime "$plain_hdr"); a_exe=$(mtime "$exe"); }
  unchanged_since_snapshot() {
    same_time "$(mtime "$lit_stamp")" "$a_lit" && same_time "$(mtime "$plain_stamp")" "$a_plain" &&
      same_time "$(mtime "$lit_hdr")" "$a_lith" && same_time "$(mtime "$plain_hdr")" "$a_plainh" &&
      same_time "$(mtime "$exe")" "$a_exe"
  }
  snapshot; tick
  if step "$logs/3-noop.log" build "$bld" && ! tool_ran "$logs/3-noop.log" && unchanged_since_snapshot; then
    pass "$gen: rebuild with nothing changed does nothing"
  else
    fail "$gen: rebuild with nothing changed does nothing"; show_log "$logs/3-noop.log"
  fi

  # touch tint.glsl: only lit_shaders re-runs; no header changes, nothing recompiles.
  snapshot; tick; touch "$tint"
  if ! step "$logs/4-touch.log" build "$bld"; then
    fail "$gen: rebuild after touching tint.glsl"; show_log "$logs/4-touch.log"; return
  fi
  check "$gen: touch tint.glsl -> lit_shaders stamp is newer" later_time "$(mtime "$lit_stamp")" "$a_lit"
  check "$gen: touch tint.glsl -> plain_shaders stamp unchanged" same_time "$(mtime "$plain_stamp")" "$a_plain"
  check "$gen: touch tint.glsl -> lit header not rewritten" same_time "$(mtime "$lit_hdr")" "$a_lith"
  check "$gen: touch tint.glsl -> plain header not rewritten" same_time "$(mtime "$plain_hdr")" "$a_plainh"
  check "$gen: touch tint.glsl -> prism_consumer not rebuilt" same_time "$(mtime "$exe")" "$a_exe"
  snapshot; tick
  if step "$logs/5-second.log" build "$bld" && ! tool_ran "$logs/5-second.log" && unchanged_since_snapshot; then
    pass "$gen: second rebuild after the touch does nothing"
  else
    fail "$gen: second rebuild after the touch does nothing"; show_log "$logs/5-second.log"
  fi

  # Edit tint.glsl's leading comment: it is the module's description, embedded in the
  # lit data file and printed by the program. The header only declares, so it keeps its
  # mtime, and the one translation unit compiled is lit's data file (issue 10, item 1).
  local token="integration-edit-$tag-$$"
  snapshot; tick
  local a_litdata; a_litdata=$(mtime "$lit_data")
  sed -i "1i // Edited by the integration test: $token." "$tint"
  if ! step "$logs/6-edit.log" build "$bld"; then
    fail "$gen: rebuild after editing tint.glsl"; show_log "$logs/6-edit.log"; return
  fi
  check "$gen: edit tint.glsl -> lit data file rewritten" later_time "$(mtime "$lit_data")" "$a_litdata"
  check "$gen: edit tint.glsl -> lit data file holds the edit" grep -q "$token" "$lit_data"
  check "$gen: edit tint.glsl -> lit header not rewritten (mtime unchanged)" same_time "$(mtime "$lit_hdr")" "$a_lith"
  local compiled; compiled=$(grep -c "Building CXX object" "$logs/6-edit.log")
  check "$gen: edit tint.glsl -> compiled units: $compiled (at most 1 per catalogue that reads it: 1)" test "$compiled" -eq 1
  check "$gen: edit tint.glsl -> the unit compiled is lit_shaders.cpp" grep -q "Building CXX object.*lit_shaders\.cpp" "$logs/6-edit.log"
  check "$gen: edit tint.glsl -> plain_shaders stamp unchanged" same_time "$(mtime "$plain_stamp")" "$a_plain"
  check "$gen: edit tint.glsl -> plain header untouched" same_time "$(mtime "$plain_hdr")" "$a_plainh"
  check "$gen: edit tint.glsl -> prism_consumer rebuilt" later_time "$(mtime "$exe")" "$a_exe"
  if run_consumer "$bld" "$src" "$moddir" "$logs/6-run.log" "$gen: after the edit"; then
    check "$gen: rebuilt prism_consumer prints the edited description" grep -q "^  module tint: .*$token" "$logs/6-run.log"
  fi

  # An include error in tint.glsl: the build fails at tint.glsl, the header survives.
  snapshot; tick
  cp "$lit_hdr" "$dir/lit_before_error.hpp"
  echo '#include <integration_missing_module.glsl>' >>"$tint"
  local line; line=$(wc -l <"$tint")
  if step "$logs/7-error.log" build "$bld"; then
    fail "$gen: include error in tint.glsl fails the build"
  else
    pass "$gen: include error in tint.glsl fails the build"
  fi
  local l found=0
  while IFS= read -r l; do
    case "$l" in
      "$tint:$line:"*) [[ "${l#"$tint:$line:"}" =~ ^[0-9]+:\ error: ]] && found=1 ;;
    esac
  done <"$logs/7-error.log"
  if [ $found = 1 ]; then
    pass "$gen: error reported as $tint:$line:<col>: error:"
  else
    fail "$gen: error reported as $tint:$line:<col>: error:"; show_log "$logs/7-error.log"
  fi
  check "$gen: failed build leaves the lit header in place, unchanged" cmp -s "$lit_hdr" "$dir/lit_before_error.hpp"
  check "$gen: failed build does not touch the lit header" same_time "$(mtime "$lit_hdr")" "$a_lith"
  check "$gen: failed build leaves no temporary header files" \
    test -z "$(find "$(dirname "$lit_hdr")" -name '*.tmp*' -print -quit)"
  check "$gen: failed build does not update the lit stamp" same_time "$(mtime "$lit_stamp")" "$a_lit"
  check "$gen: failed build leaves plain_shaders alone" same_time "$(mtime "$plain_hdr")" "$a_plainh"
  tick
  if step "$logs/8-error-again.log" build "$bld"; then
    fail "$gen: the failed step is retried (the next build fails again)"
  else
    pass "$gen: the failed step is retried (the next build fails again)"
  fi

  # Fix the error: the build recovers; the header equals the one before the error.
  sed -i '$d' "$tint"; tick
  if step "$logs/9-fixed.log" build "$bld"; then
    pass "$gen: build recovers once the include error is removed"
    check "$gen: recovered header equals the header before the error" cmp -s "$lit_hdr" "$dir/lit_before_error.hpp"
    run_consumer "$bld" "$src" "$moddir" "$logs/9-run.log" "$gen: after the fix"
  else
    fail "$gen: build recovers once the include error is removed"; show_log "$logs/9-fixed.log"
  fi

  # A new module in lit's module dir: the header lists every module of its dirs, so
  # lit_shaders must re-run although no shader includes the new file.
  snapshot; tick
  printf '// Provides: nothing; added by the integration test.\nconst float GLOW_%s = 1.0;\n' "$$" \
    >"$src/modules/lit/integration_glow.glsl"
  if step "$logs/10-new-module.log" build "$bld"; then
    check "$gen: new module -> lit header rewritten and lists it" \
      grep -q "integration_glow" "$lit_hdr"
    check "$gen: new module -> plain_shaders stamp unchanged" same_time "$(mtime "$plain_stamp")" "$a_plain"
    run_consumer "$bld" "$src" "$moddir" "$logs/10-run.log" "$gen: after the new module"
  else
    fail "$gen: build after adding a module"; show_log "$logs/10-new-module.log"
  fi
  echo "   ($gen checks took $((SECONDS - started)) s)"
}

# check_consumer_install <build dir> <log dir> <prefix>: the consumer's `cmake --install`
# writes its own program and nothing of Prism's (PRISM_INSTALL is off in a subproject).
check_consumer_install() {
  local bld=$1 logs=$2 prefix=$3
  if step "$logs/2-install.log" "$CMAKE" --install "$bld" --prefix "$prefix"; then
    local extra; extra=$(cd "$prefix" && find . -type f ! -path ./bin/prism_consumer | head -n 5)
    check "Ninja: the consumer's install holds bin/prism_consumer alone${extra:+ (also: $extra)}" \
      test -z "$extra" -a -x "$prefix/bin/prism_consumer"
  else
    fail "Ninja: cmake --install the consumer"; show_log "$logs/2-install.log"
  fi
}

# last_opt_levels <commands> <object dir>: the distinct last -O flags of the compile commands
# that write objects under <object dir> of Prism's build, one line each.
last_opt_levels() {
  grep -F -e "-o _deps/prism-build/$2/" "$1" | while IFS= read -r line; do
    grep -o -E -e " -O[^ ]*" <<<"$line" | tail -n 1 | tr -d ' '
  done | sort -u
}

# check_lean: configures a fresh copy of the consumer with Prism's defaults as a
# subproject (runtime on) and reads its build graph without building it (issue 29,
# item 1): the consumer links Prism::render, so the graph must hold the tool, render and
# what render links, and nothing else of Prism's.
check_lean() {
  local dir=$WORK/lean
  local src=$dir/consumer bld=$dir/build logs=$dir/logs prism=$dir/build/_deps/prism-build started=$SECONDS
  echo "== Ninja: the lean subproject (Prism's runtime on, graph only)"
  rm -rf "$dir"; mkdir -p "$logs"
  cp -R "$SOURCE/examples/consumer" "$src"
  if ! step "$logs/1-configure.log" "$CMAKE" -S "$src" -B "$bld" -G Ninja -DPRISM_SOURCE_DIR="$SOURCE" \
         "${COMMON_ARGS[@]}"; then
    fail "lean: configure the consumer with Prism's runtime"; show_log "$logs/1-configure.log"; return
  fi
  ninja -C "$bld" -t commands all >"$logs/commands.txt" 2>"$logs/commands.err"
  local steps; steps=$(grep -c . "$logs/commands.txt")
  check "lean: $steps build steps (at most $MAX_LEAN_STEPS)" test "$steps" -gt 0 -a "$steps" -le "$MAX_LEAN_STEPS"
  local cmds=$logs/commands.txt
  check "lean: the graph links prism-shaderc" grep -q -e "-o _deps/prism-build/shaderc_tool/prism-shaderc " "$cmds"
  check "lean: the graph archives libprism_render.a" grep -q -e "prism-build/runtime/render/libprism_render\.a " "$cmds"
  local apps; apps=$(grep -o -E "_deps/prism-build/(apps|examples|bench|tests)/[^ ]*" "$cmds" | head -n 3)
  check "lean: no Prism program, example, bench or test in the graph${apps:+ (has: $apps)}" test -z "$apps"
  local systems; systems=$(grep -o -E "_deps/prism-build/runtime/(rain|water|diffraction|bluenoise|scene|reference)/" \
                           "$cmds" | sort -u | head -n 3)
  check "lean: no system the consumer does not link in the graph${systems:+ (has: $systems)}" test -z "$systems"
  # The tool's code compiles at PRISM_SHADERC_OPT_FLAGS' -Og (the last -O of its compiles
  # wins); the runtime the consumer links at the consumer's build type (-O0 here).
  local tool_o render_o
  tool_o=$(last_opt_levels "$cmds" shaderc_tool/CMakeFiles/prism_shaderc_lib.dir)
  render_o=$(last_opt_levels "$cmds" runtime/render/CMakeFiles/prism_render.dir)
  check "lean: prism_shaderc_lib compiles at -Og (its compiles' last -O: ${tool_o:-none})" test "$tool_o" = -Og
  check "lean: prism_render compiles at the build type's -O0 (its compiles' last -O: ${render_o:-none})" \
    test "$render_o" = -O0
  local rules; rules=$(grep -l -r "file(INSTALL" "$prism" --include=cmake_install.cmake | head -n 3)
  check "lean: no install rule of Prism's${rules:+ (in: $rules)}" test -z "$rules"
  echo "   (lean checks took $((SECONDS - started)) s)"
}

# install_prism: installs this build (--build) into $PREFIX for the find_package builds;
# returns 1 when there is nothing usable to build against.
install_prism() {
  local log=$WORK/install-prism.log
  echo "== cmake --install $BUILD --prefix $PREFIX"
  rm -rf "$PREFIX"
  if [ ! -x "$BUILD/shaderc_tool/prism-shaderc" ]; then
    fail "install: no Prism build to install from ($BUILD)"; return 1
  fi
  if ! step "$log" "$CMAKE" --install "$BUILD" --prefix "$PREFIX"; then
    fail "install: cmake --install Prism into $PREFIX"; show_log "$log"; return 1
  fi
  pass "install: cmake --install Prism into $PREFIX"
  local config; config=$(find "$PREFIX" -name PrismConfig.cmake -print -quit)
  check "install: prefix has bin/prism-shaderc" test -x "$PREFIX/bin/prism-shaderc"
  check "install: prefix has include/prism/catalog/shader_catalog.hpp" \
    test -f "$PREFIX/include/prism/catalog/shader_catalog.hpp"
  check "install: prefix has share/prism/modules/contract.json" test -f "$PREFIX/share/prism/modules/contract.json"
  check "install: prefix has PrismConfig.cmake and PrismShaders.cmake" \
    test -n "$config" -a -f "$(dirname "${config:-/nonexistent}")/PrismShaders.cmake"
}

# check_installed: builds a fresh copy of the consumer with Ninja and find_package against
# install_prism's prefix.
check_installed() {
  local prefix=$PREFIX dir=$WORK/installed
  local src=$dir/consumer bld=$dir/build logs=$dir/logs
  local started=$SECONDS
  echo "== Ninja: find_package(Prism) from an install prefix"
  rm -rf "$dir"; mkdir -p "$logs"

  cp -R "$SOURCE/examples/consumer" "$src"
  if ! step "$logs/2-configure.log" "$CMAKE" -S "$src" -B "$bld" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
         "${COMMON_ARGS[@]}"; then
    fail "installed: configure the consumer with find_package(Prism)"; show_log "$logs/2-configure.log"; return
  fi
  pass "installed: configure the consumer with find_package(Prism)"
  local prism_dir; prism_dir=$(sed -n 's/^Prism_DIR:[A-Z]*=//p' "$bld/CMakeCache.txt")
  check "installed: Prism_DIR is inside the prefix ($prism_dir)" test "${prism_dir#"$prefix"/}" != "$prism_dir"
  if ! step "$logs/3-build.log" build "$bld"; then
    fail "installed: build the consumer"; show_log "$logs/3-build.log"; return
  fi
  pass "installed: build the consumer"
  check "installed: nothing of Prism was compiled" test ! -e "$bld/prism"
  check "installed: the installed prism-shaderc ran" grep -q -F "$prefix/bin/prism-shaderc" "$bld/build.ninja"
  check "installed: lit_shaders read the installed modules" grep -q -F "$prefix/share/prism/modules/lighting.glsl" "$bld/lit_shaders.d"
  run_consumer "$bld" "$src" "$prefix/share/prism/modules" "$logs/3-run.log" "installed"
  local before; before=$(mtime "$bld/lit_shaders.stamp"); tick
  if step "$logs/4-noop.log" build "$bld" && ! tool_ran "$logs/4-noop.log" &&
     same_time "$(mtime "$bld/lit_shaders.stamp")" "$before"; then
    pass "installed: rebuild with nothing changed does nothing"
  else
    fail "installed: rebuild with nothing changed does nothing"; show_log "$logs/4-noop.log"
  fi

  # A consumer whose cmake_minimum_required() predates CMP0116 (depfile paths relative
  # to the build dir for Ninja) must get the same no-op rebuild: prism_add_shaders()
  # pins its own policies.
  local old_src=$dir/consumer-3.16 old_bld=$dir/build-3.16
  cp -R "$SOURCE/examples/consumer" "$old_src"
  sed -i 's/^cmake_minimum_required(VERSION [0-9.]*)/cmake_minimum_required(VERSION 3.16)/' "$old_src/CMakeLists.txt"
  if ! grep -q '^cmake_minimum_required(VERSION 3.16)' "$old_src/CMakeLists.txt"; then
    fail "installed, CMake 3.16 policies: could not lower cmake_minimum_required in the copy"
  elif step "$logs/5-old-configure.log" "$CMAKE" -S "$old_src" -B "$old_bld" -G Ninja \
         -DCMAKE_PREFIX_PATH="$prefix" "${COMMON_ARGS[@]}" &&
       step "$logs/5-old-build.log" build "$old_bld"; then
    before=$(mtime "$old_bld/lit_shaders.stamp"); tick
    if step "$logs/5-old-noop.log" build "$old_bld" && ! tool_ran "$logs/5-old-noop.log" &&
       same_time "$(mtime "$old_bld/lit_shaders.stamp")" "$before"; then
      pass "installed, CMake 3.16 policies: rebuild with nothing changed does nothing"
    else
      fail "installed, CMake 3.16 policies: rebuild with nothing changed does nothing"; show_log "$logs/5-old-noop.log"
    fi
  else
    fail "installed, CMake 3.16 policies: configure and build the consumer"
    if [ -f "$logs/5-old-build.log" ]; then show_log "$logs/5-old-build.log"; else show_log "$logs/5-old-configure.log"; fi
  fi
  echo "   (install checks took $((SECONDS - started)) s)"
}

echo "consumer_build: Prism at $SOURCE, scratch $WORK, mtime tick ${TICK}s"
have_ninja=1
command -v ninja >/dev/null 2>&1 || { fail "Ninja: 'ninja' not found (scripts/setup.sh installs ninja-build)"; have_ninja=0; }
[ $have_ninja = 1 ] && check_generator ninja Ninja "$SOURCE/modules" "FetchContent_Declare(prism SOURCE_DIR $SOURCE)" \
  -DPRISM_SOURCE_DIR="$SOURCE" "${PRISM_ARGS[@]}"
installed=0
install_prism && installed=1
if ! command -v make >/dev/null 2>&1; then
  fail "Unix Makefiles: 'make' not found (scripts/setup.sh installs build-essential)"
elif [ $installed = 1 ]; then
  check_generator make "Unix Makefiles" "$PREFIX/share/prism/modules" "find_package(Prism) from $PREFIX" \
    -DCMAKE_PREFIX_PATH="$PREFIX"
fi
[ $have_ninja = 1 ] && [ $installed = 1 ] && check_installed
[ $have_ninja = 1 ] && check_lean
[ $have_ninja = 1 ] && check_install_preset

echo "consumer_build: $FAILURES failed check(s) in $SECONDS s"
[ "$FAILURES" -eq 0 ]
