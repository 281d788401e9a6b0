// The switches a person sets when running the tests by hand (PRISM_UPDATE_GOLDENS=1,
// PRISM_SAVE_ACTUAL=1): tests read them with envFlag, never in CI.
//
//     #include "prism/test/env_flag.hpp"
//
//     if (prism::test::envFlag("PRISM_UPDATE_GOLDENS")) GTEST_SKIP() << "goldens are being rewritten";
#pragma once

namespace prism::test {

// True when the variable is set to anything but "", "0", "false", "FALSE" or "off".
bool envFlag(const char* name);

}  // namespace prism::test
