#!/usr/bin/env bash
# Runs the GPU-vs-CPU agreement tests and the GPU benches on a machine with a real GPU and
# no display (docs/gpu.md): EGL on the device platform, the test binaries of a build tree.
#   scripts/gpu-agreement.sh BUILD_DIR [OUT_DIR]
# BUILD_DIR needs -DPRISM_BUILD_BENCH=ON; logs go to OUT_DIR (default gpu-agreement/).
set -uo pipefail
build=${1:?usage: scripts/gpu-agreement.sh BUILD_DIR [OUT_DIR]}
out=${2:-gpu-agreement}
mkdir -p "$out"
export PRISM_EGL_PLATFORM=${PRISM_EGL_PLATFORM:-device}
status=0
run() {
  local name=$1; shift
  echo "=== $name"
  if ! "$@" > "$out/$name.log" 2>&1; then status=1; fi
  grep -E "PASSED|FAILED TEST|target|^\| " "$out/$name.log" | tail -12
}
run gl_context  "$build/tests/gl/prism_gl_gl_tests" --gtest_filter='EglContext.*:ContextLifetime.*'
run water_gl    "$build/tests/water/prism_water_gl_tests" --gtest_filter='-*Golden*'
run diffraction "$build/tests/diffraction/prism_diffraction_gl_tests"
run rendering   "$build/tests/rendering/prism_rendering_gl_tests" --gtest_filter='-*Golden*'
run rain_gl     "$build/tests/rain/prism_rain_gl_tests" --gtest_filter='-*Golden*'
run bluenoise   "$build/tests/bluenoise/prism_bluenoise_gl_tests"
run bench_water "$build/bench/water/prism_bench_water" --grids 128 256 512 1024
run bench_diffraction_scene "$build/bench/diffraction/prism_bench_diffraction_scene" --frames 7
run bench_rain  "$build/bench/rain/prism_bench_rain" --out "$out" --min-exp 14 --max-exp 22
exit $status
