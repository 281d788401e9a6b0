#!/usr/bin/env bash
# The sanitizer tier (docs/reliability.md): builds the unit- and GL-tier tests with
# Clang 14, AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer
# (-fno-sanitize-recover: the first error fails the test) and runs them with CTest.
#
#   scripts/run-sanitizer-tests.sh [--build-dir DIR] [--no-build] [extra ctest args]
#
# Only the test executables of those two tiers are built (not the examples, the
# renderer apps or the benchmarks) to keep CI within its budget. Leaks inside Mesa,
# which Prism cannot fix, are suppressed by tests/sanitizers/lsan.supp; each entry
# there gives its reason, and nothing of Prism's own code is suppressed.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD_DIR=build-san
BUILD=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) BUILD_DIR=$2; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    *) break ;;
  esac
done

# The unit (label unit) and GL (label gl) test executables (tests/README.md: prism_<subject>_tests
# and prism_<subject>_gl_tests); prism_scene_cli_tests also builds prism-render, which it runs.
TEST_TARGETS=(prism_shaderc_tests prism_shaderc_gl_tests prism_geometry_tests prism_image_tests prism_gl_tests prism_gl_gl_tests
  prism_rain_tests prism_rain_gl_tests prism_water_tests prism_water_gl_tests prism_scene_tests prism_scene_gl_tests
  prism_scene_cli_tests prism_limits_tests prism_draw_state_gl_tests)
if [ "$BUILD" = 1 ]; then
  bash scripts/configure-sanitizer-build.sh "$BUILD_DIR"
  cmake --build "$BUILD_DIR" --target "${TEST_TARGETS[@]}" -j "$(nproc)"
  echo "run-sanitizer-tests: configured and built in $SECONDS s"
fi

# Mesa's EGL unloads its driver at eglTerminate; memory the driver's globals still
# point to then looks leaked from "<unknown module>". Keeping libraries loaded removes
# those false reports without suppressing anything (tests/sanitizers/keep_dlopened.c).
clang-14 -shared -fPIC -O1 -o "$BUILD_DIR/keep_dlopened.so" tests/sanitizers/keep_dlopened.c
export LD_PRELOAD=$ROOT/$BUILD_DIR/keep_dlopened.so
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$ROOT/tests/sanitizers/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Examples, snippets and the newer systems' CLI and doc checks are not built in this tier (their
# executables are not in TEST_TARGETS); integration and rendering tiers run in the main build.
NOT_BUILT='(example|snippets|architecture|hotreload|diffraction|bluenoise)\..*'
# Endurance runs that repeat, for minutes under ASan, code that shorter tests of this tier
# already cover: 10,000-step mass ledgers (the step itself: water.WaterStep.*, water.Cases/GpuCpuAgreement.*), the
# fast CPU step at every thread count (one count: water.FastCpuStep.*; races are not ASan's
# to find), the CD disc (79 s here; its code is the grating's and the snake's, whose goldens
# run: only its tables are larger), the puddles close-up (22 s; the water and rain goldens
# run its code), and every system drawn before rain (36 s; each system's own tests and
# draw_state.DrawStateTest.SceneRendererRestoresTheState run the same save and restore).
# They run in the main build's tier.
ENDURANCE='water\.MassLedger\..*|water\.WaterGlTest\.GpuMassLedgerHoldsOver10000Steps|'
ENDURANCE+='water\.FastCpuStep\.IsBitIdenticalToTheFirstStepForEveryThreadCount|SceneCli\.render_diffraction_cd|'
ENDURANCE+='ExampleScenes/SceneGolden\.MatchesTheGoldenImage/"(diffraction_cd|puddles_closeup)"|'
ENDURANCE+='draw_state\.DrawStateTest\.RainAfterEveryOtherSystemMatchesRainAlone|'
# The real corpus (about 125 programs of public codebases, each also run through glslc, spirv-val,
# spirv-cross and glslangValidator: most of its time is theirs) is a differential test of verdicts, lines and
# reflection, which ASan does not change, and so is compiling the block structs of every corpus program; the
# seed corpus's vk_* cases and the BlockStructs tests run the same paths of Prism (ES compute, per-stage
# linking, layout rules, vertex-only and mesh programs, reflection, structs) in this tier, and the fuzz tier
# runs them under ASan too.
ENDURANCE+='Programs/ReferenceCorpusRealCode\..*|ReferenceCorpusChecks\.BlockStructsOfEveryAcceptedVulkanProgramCompile'
ctest --test-dir "$BUILD_DIR" -L '^(unit|gl)$' -E "^($NOT_BUILT|$ENDURANCE)\$" --output-on-failure -j "$(nproc)" \
  --timeout 900 "$@"
