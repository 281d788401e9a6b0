#!/usr/bin/env bash
# Configures the Clang 14 build with ASan + UBSan and libFuzzer coverage that both
# scripts/run-sanitizer-tests.sh and scripts/run-fuzzers.sh use (one build, two tiers).
# Usage: scripts/configure-sanitizer-build.sh [BUILD_DIR]   (default build-san)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build-san}
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# -O1: the usual optimisation for sanitizer builds; it compiles faster than -O3 and
# keeps reports readable. The test binaries' own code (PRISM_TEST_OPT_FLAGS: fixtures and
# assertions; the libraries under test stay at -O1) compiles at -O0: with ASan's
# instrumentation Clang's -O1 took 2.5 times -O0's CPU time on the shaderc tests' largest
# batch (docs/ci.md), and -O0 elides no access that the sanitizers check.
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 -DCMAKE_C_FLAGS_RELEASE=-O1 \
  -DPRISM_TEST_OPT_FLAGS=-O0 \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" \
  -DPRISM_SANITIZE=address,undefined -DPRISM_BUILD_FUZZERS=ON \
  -DPRISM_BUILD_RUNTIME=ON -DPRISM_BUILD_TESTS=ON -DPRISM_BUILD_EXAMPLES=OFF -DPRISM_BUILD_BENCH=OFF >/dev/null
