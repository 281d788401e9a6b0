#!/usr/bin/env bash
# The sanitizer tier (docs/reliability.md): builds the unit-tier tests with Clang 14,
# AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer
# (-fno-sanitize-recover: the first error fails the test) and runs them with CTest.
#
#   scripts/run-sanitizer-tests.sh [--build-dir DIR] [--no-build | --build-only] [extra ctest args]
#
# Only the unit tier's test executables are built: the code where sanitizers find bugs, the
# readers of untrusted input (GLSL and its preprocessor, contract and scene JSON, OBJ, PNG maps),
# the tool's stages and the CPU simulations. The GL tier is left to the main build (docs/ci.md:
# it was a third of this tier's time): its tests spend their time in Mesa, which is not
# instrumented, behind Prism's GL calls; in the project's record (docs/reliability.md, "Bugs found
# and fixed") this tier found one bug, in the OBJ loader, and its GL tests reported only Mesa's own
# leaks (tests/sanitizers/lsan.supp). Leaks inside Mesa, which Prism cannot fix, are suppressed
# there; each entry gives its reason, and nothing of Prism's own code is suppressed.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD_DIR=build-san
BUILD=1
TEST=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) BUILD_DIR=$2; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    --build-only) TEST=0; shift ;;
    *) break ;;
  esac
done

# The unit-tier test executables (label unit; tests/README.md: prism_<subject>_tests).
TEST_TARGETS=(prism_shaderc_tests prism_geometry_tests prism_image_tests prism_gl_tests prism_rain_tests
  prism_water_tests prism_scene_tests prism_limits_tests)
if [ "$BUILD" = 1 ]; then
  bash scripts/configure-sanitizer-build.sh "$BUILD_DIR"
  cmake --build "$BUILD_DIR" --target "${TEST_TARGETS[@]}" -j "$(nproc)"
  echo "run-sanitizer-tests: configured and built in $SECONDS s"
fi
[ "$TEST" = 1 ] || exit 0

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
# already cover: 10,000-step mass ledgers (the step itself: water.WaterStep.*) and the fast CPU
# step at every thread count (one count: water.FastCpuStep.*; races are not ASan's to find).
# They run in the main build's tier.
ENDURANCE='water\.MassLedger\..*|water\.FastCpuStep\.IsBitIdenticalToTheFirstStepForEveryThreadCount|'
# The real corpus (about 125 programs of public codebases, each also run through glslc, spirv-val,
# spirv-cross and glslangValidator: most of its time is theirs) is a differential test of verdicts, lines and
# reflection, which ASan does not change, and so is compiling the block structs of every corpus program; the
# seed corpus's vk_* cases and the BlockStructs tests run the same paths of Prism (ES compute, per-stage
# linking, layout rules, vertex-only and mesh programs, reflection, structs) in this tier, and the fuzz tier
# runs them under ASan too.
ENDURANCE+='Programs/ReferenceCorpusRealCode\..*|ReferenceCorpusChecks\.BlockStructsOfEveryAcceptedVulkanProgramCompile|'
# Every program of the project's catalogues through the es300 and SPIR-V targets, then glslangValidator and
# spirv-val over each output (56 s here under ASan, of 871 tests' 497 s): this tier's own build already runs
# the ASan-built prism-shaderc over most of those programs for those targets (the project, diffraction and
# blue-noise catalogues are built for gl, es300 and spirv, with an empty validation cache in a fresh build;
# rain's and water's are built for gl, their es300 and SPIR-V take the same code paths), and the reference
# tools' half is the same work in both tiers.
ENDURANCE+='Targets\.EveryEs300ProgramOfTheProjectValidatesAndLinks|Targets\.EverySpirvModuleOfTheProjectPassesTheValidator'
# Checks that run no code of this build (clang-format over the tree, the report's Python generator) give
# the same answer in both tiers: they run in the main tier only.
NO_BUILT_CODE='format(\..*)?|report\..*'
ctest --test-dir "$BUILD_DIR" -L '^unit$' -E "^($NOT_BUILT|$NO_BUILT_CODE|$ENDURANCE)\$" --output-on-failure -j "$(nproc)" \
  --timeout 900 "$@"
