// The switches a person sets when running the tests by hand (the golden switches of
// prism/test/golden.hpp, PRISM_VULKAN_REPORT, ...): tests read them with envFlag, never in CI.
//
//     #include "prism/test/env_flag.hpp"
//
//     if (prism::test::envFlag("PRISM_SAVE_ACTUAL")) std::puts("saving every case's images");
#pragma once

namespace prism::test {

// True when the variable is set to anything but "", "0", "false", "FALSE" or "off".
bool envFlag(const char* name);

}  // namespace prism::test
