// Shared by the diffraction GL tests: the test grating (2500 nm period, 60 nm amplitude) and a
// fixture that holds one headless GL context per test suite.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <memory>
#include <string>

#include "prism/diffraction/diffraction_gl.hpp"
#include "prism/gl/gl_context.hpp"

namespace prism::diffraction::test {

inline const StamBrdf& testGrating() {
    static const StamBrdf brdf(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 60.0, .periods = 8}),
                               {.tolerance = 1e-5, .window = GaussianWindow{1000.0, 4.0}});
    return brdf;
}

class GlSuite : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        try {
            context_ = prism::gl::createContext();
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        ASSERT_NE(context_, nullptr) << "no GL context: " << error_;
        context_->makeCurrent();
    }

    static inline std::unique_ptr<prism::gl::Context> context_;
    static inline std::string error_;
};

}  // namespace prism::diffraction::test
