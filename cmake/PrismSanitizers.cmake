# Sanitizer and fuzzing builds (docs/reliability.md).
#   -DPRISM_SANITIZE=address,undefined   every target built with ASan and UBSan; UBSan stops at
#                                        the first error (-fno-sanitize-recover=all).
#   -DPRISM_BUILD_FUZZERS=ON             (Clang only) also instruments every target for libFuzzer
#                                        coverage and builds the harnesses of tests/fuzz/.
# Debian's glslang is built without RTTI, so UBSan's vptr check cannot link against it
# ("undefined reference to typeinfo for glslang::TProgram"): it is always left out.
set(PRISM_SANITIZE "" CACHE STRING "Comma-separated sanitizers for every target, e.g. address,undefined")
option(PRISM_BUILD_FUZZERS "Build the libFuzzer harnesses of tests/fuzz (Clang only)" OFF)

if(PRISM_BUILD_FUZZERS AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "PRISM_BUILD_FUZZERS needs Clang (libFuzzer), e.g. -DCMAKE_CXX_COMPILER=clang++-14")
endif()
if(PRISM_BUILD_FUZZERS AND NOT PRISM_SANITIZE)
  set(PRISM_SANITIZE "address,undefined" CACHE STRING "" FORCE)
endif()

if(PRISM_SANITIZE)
  set(prism_sanitize_flags -fsanitize=${PRISM_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  if(PRISM_SANITIZE MATCHES "undefined")
    list(APPEND prism_sanitize_flags -fno-sanitize=vptr)
  endif()
  add_compile_options(${prism_sanitize_flags})
  add_link_options(${prism_sanitize_flags})
  # Line tables are enough for symbolized reports and keep the build fast.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options(-gline-tables-only)
  else()
    add_compile_options(-g1)
  endif()
endif()

if(PRISM_BUILD_FUZZERS)
  # Coverage feedback for libFuzzer in every library; only the harnesses link its main().
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
