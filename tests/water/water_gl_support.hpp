// The GL tier of the water tests: one GL 4.3 core context per test process (Mesa
// llvmpipe through EGL surfaceless, or OSMesa), made current before each test.
#pragma once

#include <gtest/gtest.h>

#include "prism/gl/gl_context.hpp"

namespace prism::water::test {

gl::Context* glContext();  // nullptr when it could not be created
const std::string& glContextError();

// Base fixture: fails (never skips) without a 4.3 context, since a GL tier that
// silently skips would hide a broken headless setup.
class WaterGlTest : public ::testing::Test {
  protected:
    void SetUp() override;
};

}  // namespace prism::water::test
