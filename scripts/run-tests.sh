#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine (idempotent), builds everything and runs every test
# tier (unit, GL, rendering, integration, browser: the gallery report in headless Chromium,
# tests/report; gui: the viewer under xvfb-run) with CTest (no -L filter: every label runs),
# then the sanitizer and fuzz tiers
# (docs/reliability.md). This is what .ci/run calls.
# Benchmarks are not tests: they are built here (so they cannot rot) and run on their own
# (see docs/).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase's wall time and CPU time, printed as it ends, then all of them as the rows of
# docs/ci.md's table (CI's budget). CPU time: user + system of the finished child processes
# (fields cutime and cstime of /proc/self/stat, in clock ticks), so a phase's builds and tests count.
ticks_per_s=$(getconf CLK_TCK)
children_cpu_ticks() { local f; read -r -a f <"/proc/$$/stat"; echo $((f[15] + f[16])); }
phase_start=$SECONDS phase_cpu_start=$(children_cpu_ticks) phase_rows=""
phase() {
  local wall=$((SECONDS - phase_start)) cpu=$((($(children_cpu_ticks) - phase_cpu_start) / ticks_per_s))
  echo "run-tests: phase '$1' took $wall s, $cpu s CPU (total $SECONDS s)"
  phase_rows+="| $1 | $wall | $cpu |"$'\n'
  phase_start=$SECONDS phase_cpu_start=$(children_cpu_ticks)
}
bash scripts/setup.sh
phase setup
BUILD_DIR=${BUILD_DIR:-build}
# The benchmarks are built, not run, here: their own code at -O1 (PRISM_BENCH_OPT_FLAGS, docs/ci.md).
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPRISM_BUILD_RUNTIME=ON -DPRISM_BUILD_TESTS=ON -DPRISM_BUILD_EXAMPLES=ON -DPRISM_BUILD_BENCH=ON \
  -DPRISM_BENCH_OPT_FLAGS=-O1
cmake --build "$BUILD_DIR" -j "$(nproc)"
phase "main build"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)" --timeout 900
phase "main tests"
# The sanitizer and fuzz tiers' Clang build (ASan, UBSan, libFuzzer), after the main tests: run
# beside them at nice 19 it doubled their wall time (the tests use both cores; docs/ci.md).
SAN_BUILD_DIR=${SAN_BUILD_DIR:-build-san}
bash scripts/run-sanitizer-tests.sh --build-dir "$SAN_BUILD_DIR" --build-only
cmake --build "$SAN_BUILD_DIR" --target prism_fuzzers -j "$(nproc)"
phase "sanitizer and fuzz build"

# Sanitizer tier: the unit tests again, built with Clang 14, ASan and UBSan; then
# the fuzz tier (label fuzz): each libFuzzer harness over its committed corpus and for
# PRISM_FUZZ_SECONDS (15) s, in the same build.
bash scripts/run-sanitizer-tests.sh --build-dir "$SAN_BUILD_DIR" --no-build
phase "sanitizer tests"
ctest --test-dir "$SAN_BUILD_DIR" -L '^fuzz$' --output-on-failure -j "$(nproc)"
phase "fuzz tests"
printf 'run-tests: every phase (docs/ci.md), %s s in all\n| phase | wall s | CPU s |\n|---|---:|---:|\n%s' \
  "$SECONDS" "$phase_rows"
