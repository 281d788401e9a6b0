#!/usr/bin/env bash
# Runs Prism's libFuzzer harnesses (tests/fuzz, docs/reliability.md).
#
#   scripts/run-fuzzers.sh                      build (Clang 14, ASan+UBSan+libFuzzer) and fuzz
#                                               every harness for 15 s, as CI does
#   scripts/run-fuzzers.sh --seconds 600 obj_loader      longer local run of one harness
#   scripts/run-fuzzers.sh --corpus-only        run each committed corpus input once
#
# Options: --build-dir DIR (default build-san, shared with run-sanitizer-tests.sh),
# --no-build, --seconds N, --corpus-only, then harness names (default: all built).
# Each run fails on any crash, leak, timeout (-timeout=5 s per input) or out-of-memory
# (-rss_limit_mb=2048, and any one allocation over 1 GB: -malloc_limit_mb=1024). Inputs
# the fuzzer finds go to DIR/fuzz-work/<target>/ (never into the source tree); a failing
# input is saved as DIR/fuzz-artifacts/<target>/crash-* (or oom-*, timeout-*, leak-*), to
# be added to tests/fuzz/corpus/<target>/ as regress-*.<ext> once the bug is fixed.
# Executions and coverage of each run are appended to DIR/fuzz-stats.tsv.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD_DIR=build-san
BUILD=1
SECONDS_EACH=15
CORPUS_ONLY=0
TARGETS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) BUILD_DIR=$2; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    --seconds) SECONDS_EACH=$2; shift 2 ;;
    --corpus-only) CORPUS_ONLY=1; shift ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    -*) echo "run-fuzzers: unknown option $1" >&2; exit 2 ;;
    *) TARGETS+=("$1"); shift ;;
  esac
done

if [ "$BUILD" = 1 ]; then
  bash scripts/configure-sanitizer-build.sh "$BUILD_DIR"
  cmake --build "$BUILD_DIR" --target prism_fuzzers -j "$(nproc)"
fi
if [ ${#TARGETS[@]} -eq 0 ]; then
  for exe in "$BUILD_DIR"/tests/fuzz/prism_fuzz_*; do TARGETS+=("${exe##*/prism_fuzz_}"); done
fi

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for target in "${TARGETS[@]}"; do
  exe=$BUILD_DIR/tests/fuzz/prism_fuzz_$target
  seeds=$ROOT/tests/fuzz/corpus/$target
  [ -x "$exe" ] || { echo "run-fuzzers: $exe is not built" >&2; exit 2; }
  [ -d "$seeds" ] || { echo "run-fuzzers: no seed corpus $seeds" >&2; exit 2; }
  artifacts=$BUILD_DIR/fuzz-artifacts/$target
  mkdir -p "$artifacts"
  if [ "$CORPUS_ONLY" = 1 ]; then
    echo "run-fuzzers: $target: every input of $seeds once"
    "$exe" -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix="$artifacts/" "$seeds"/* >"$artifacts/corpus.log" 2>&1 || {
      status=1; tail -40 "$artifacts/corpus.log"; echo "run-fuzzers: $target: FAILED on a corpus input"; }
    continue
  fi
  work=$BUILD_DIR/fuzz-work/$target
  mkdir -p "$work"
  dict=()
  [ -f "$ROOT/tests/fuzz/dict/$target.dict" ] && dict=(-dict="$ROOT/tests/fuzz/dict/$target.dict")
  log=$artifacts/fuzz.log
  echo "run-fuzzers: $target: fuzzing for $SECONDS_EACH s"
  started=$(date +%s)
  if "$exe" -max_total_time="$SECONDS_EACH" -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 \
      -artifact_prefix="$artifacts/" "${dict[@]}" "$work" "$seeds" >"$log" 2>&1; then
    result=ok
  else
    result=FAILED; status=1
    tail -60 "$log"
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || echo "cov: ? ft: ?")
  pcs=$(grep -o 'PC tables ([0-9]* PCs)' "$log" | grep -o '[0-9][0-9]*' | tail -1 || echo "?")
  corpus=$(ls "$work" | wc -l)
  printf '%s\t%s\t%s s\t%s executions\t%s of %s instrumented edges\t%s inputs in corpus\t%s\n' \
    "$(date -u +%FT%TZ)" "$target" "$(( $(date +%s) - started ))" "$runs" "$cov" "$pcs" "$corpus" "$result" |
    tee -a "$BUILD_DIR/fuzz-stats.tsv"
done
exit $status
