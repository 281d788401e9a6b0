// Test helper: golden text files in tests/shaderc/baseResults (glslang's baseResults
// idea). A run with PRISM_UPDATE_BASELINES=1 rewrites them and checks nothing.
//
//   expectMatchesBaseline(readFile(dir / "catalogue.hpp"), "catalogue.hpp");
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace prism::test {

inline bool baselineUpdateMode() {
    const char* v = std::getenv("PRISM_UPDATE_BASELINES");
    return v && std::string(v) == "1";
}

inline void expectMatchesBaseline(const std::string& actual, const std::string& name) {
    const std::filesystem::path baseline = std::filesystem::path(PRISM_SOURCE_DIR) / "tests/shaderc/baseResults" / name;
    if (baselineUpdateMode()) {
        writeFile(baseline, actual);
        GTEST_SKIP() << "rewrote " << baseline << " (PRISM_UPDATE_BASELINES=1); this run checked nothing";
    }
    ASSERT_TRUE(std::filesystem::exists(baseline))
        << baseline << " is missing; run with PRISM_UPDATE_BASELINES=1 to create it";
    EXPECT_TRUE(actual == readFile(baseline))
        << "generated text differs from " << baseline
        << "; inspect the difference and, if intended, rerun with PRISM_UPDATE_BASELINES=1";
}

}  // namespace prism::test
