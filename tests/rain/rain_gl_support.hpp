// The GL tier of the rain tests: one GL 4.3 context per test binary (a gtest
// environment; Mesa llvmpipe through EGL surfaceless unless PRISM_GL_BACKEND says
// otherwise), one shared RainPrograms, and a fixture that FAILS without a context: a
// rain tier that silently skipped would hide a broken headless setup.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "prism/gl/gl_context.hpp"
#include "prism/rain/rain_programs.hpp"

namespace prism::rain::test {

gl::Context* context();
const std::string& contextError();
RainPrograms& programs();

class RainGlTest : public ::testing::Test {
  protected:
    void SetUp() override;
};

// True when the environment variable is set to something other than "", "0" or "false".
bool envFlag(const char* name);

}  // namespace prism::rain::test
