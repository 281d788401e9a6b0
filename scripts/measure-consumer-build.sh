#!/usr/bin/env bash
# Measures a cold build of examples/consumer with Prism as a FetchContent subproject (the
# issue 29 target: at most 60 s wall at -j2; docs/using-prism.md): Release, Ninja, no
# ccache, Prism's runtime on. Prints wall, user and system time beside the target, the
# build's step count, the steps that took the most CPU time, and how long prism-shaderc
# takes to build Prism's classic catalogue and the consumer's lit catalogue.
#
# Usage: scripts/measure-consumer-build.sh [--work <dir>] [--jobs <n>] [--top <n>] [-- <cmake args...>]
#   e.g. scripts/measure-consumer-build.sh -- -DPRISM_SHADERC_OPT_FLAGS=   (the tool at the build type's -O3)
#        scripts/measure-consumer-build.sh --tool-times <consumer build dir>   (only the tool's run times)
# Wall time depends on what else the machine runs (it prints the load average); user + sys
# time much less so. Each compile runs under /usr/bin/time (the launcher below) to give
# the per-step CPU time.
set -euo pipefail

if [ "${1:-}" = --time-step ]; then  # launcher mode: --time-step <log> <compiler> <args...>
  log=$2; shift 2
  out=unknown prev=""
  for a in "$@"; do [ "$prev" = -o ] && out=$a; prev=$a; done
  times=$(mktemp)
  status=0
  /usr/bin/time -f "%U %S" -o "$times" "$@" || status=$?
  echo "$(tail -n 1 "$times") $out" >>"$log"
  rm -f "$times"
  exit "$status"
fi

# time_tool <build dir> <stamp> <what>: runs the tool's command for a catalogue three times
# into a scratch folder, with no validation cache (a real run, not the up-to-date check),
# and prints the fastest run's wall, user and system time.
time_tool() {
  local cmd; cmd=$(ninja -C "$1" -t commands "$2" | tail -n 1)
  local dir=${cmd#cd }; dir=${dir%% && *}
  cmd=${cmd#* && }  # cd <dir> && <tool command> && <depfile transform>
  local -a words; read -r -a words <<<"${cmd%% && *}"
  local scratch i best="" t
  scratch=$(mktemp -d)
  for ((i = 1; i < ${#words[@]}; i++)); do
    case "${words[i - 1]}" in
      -o | --depfile | --stamp | --emit-web) words[i]=$scratch/out/$(basename "${words[i]}") ;;
    esac
  done
  for _ in 1 2 3; do
    rm -rf "$scratch/out"; mkdir -p "$scratch/out"
    (cd "$dir" && /usr/bin/time -f "%e s wall, %U s user, %S s sys" -o "$scratch/time.txt" "${words[@]}" \
      --cache-dir none >/dev/null 2>&1)
    t=$(tail -n 1 "$scratch/time.txt")
    if [ -z "$best" ] || awk -v a="${t%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then best=$t; fi
  done
  rm -rf "$scratch"
  echo "prism-shaderc on $3: $best (the fastest of 3 runs)"
}
tool_times() {
  time_tool "$1" _deps/prism-build/prism_shaders.stamp "Prism's classic catalogue (gl, es300, spirv, web)"
  time_tool "$1" lit_shaders.stamp "the consumer's lit catalogue"
}
if [ "${1:-}" = --tool-times ]; then
  tool_times "$2"
  exit
fi

SOURCE=$(cd "$(dirname "$0")/.." && pwd -P)
WORK=/tmp/prism-consumer-build JOBS=2 TOP=12
while [ $# -gt 0 ]; do
  case "$1" in
    --work) WORK=$2; shift 2 ;;
    --jobs) JOBS=$2; shift 2 ;;
    --top) TOP=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "measure-consumer-build.sh: unknown argument '$1' (see the usage in the script)" >&2; exit 2 ;;
  esac
done
[ -x /usr/bin/time ] || { echo "measure-consumer-build.sh: needs /usr/bin/time (Debian: time)" >&2; exit 2; }
export CCACHE_DISABLE=1  # cold even where the compiler is a ccache link
unset CMAKE_GENERATOR CMAKE_BUILD_PARALLEL_LEVEL MAKEFLAGS

BLD=$WORK/build STEPS=$WORK/steps.txt
rm -rf "$WORK"; mkdir -p "$WORK"; : >"$STEPS"
launcher="$(command -v bash);$SOURCE/scripts/measure-consumer-build.sh;--time-step;$STEPS"
cmake -S "$SOURCE/examples/consumer" -B "$BLD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPRISM_SOURCE_DIR="$SOURCE" \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher" "$@" >"$WORK/configure.log"
steps=$(ninja -C "$BLD" -t commands all | grep -c .)
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
/usr/bin/time -f "%e %U %S" -o "$WORK/time.txt" cmake --build "$BLD" --parallel "$JOBS" >"$WORK/build.log"
read -r wall user sys <"$WORK/time.txt"
echo "consumer build (Release, -j$JOBS, $steps steps): $wall s wall, $user s user, $sys s sys;" \
  "target 60 s wall at -j2 (load average before: $load_before, after: $(cut -d' ' -f1-3 /proc/loadavg))"
compile_cpu=$(awk '{ s += $1 + $2 } END { printf "%.1f", s }' "$STEPS")
echo "CPU time of the compiles: $compile_cpu s; the $TOP largest (user + sys):"
awk '{ printf "%7.1f s  %s\n", $1 + $2, $3 }' "$STEPS" | sort -rn | head -n "$TOP" | sed "s|$BLD/||"

tool_times "$BLD"
