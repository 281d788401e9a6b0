// Test helper: resolves in-memory stage files and validates them as one program with
// glslang, the way prism-shaderc does for one variant.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contract.hpp"
#include "include_resolver.hpp"
#include "source_reader.hpp"
#include "validator.hpp"

namespace prism::test {

class GlslangEnvironment : public ::testing::Environment {
  public:
    void SetUp() override { shaderc::initializeValidator(); }
    void TearDown() override { shaderc::finalizeValidator(); }
};

struct InMemoryStage {
    catalog::Stage stage;
    std::string path;
};

inline shaderc::ValidatedVariant validateInMemory(const shaderc::MemoryReader& files,
                                                  const std::vector<InMemoryStage>& stages,
                                                  const shaderc::Contract& contract = {},
                                                  std::vector<std::string> includeDirs = {}) {
    shaderc::ResolveOptions options;
    options.includeDirs = std::move(includeDirs);
    std::vector<shaderc::StageToValidate> toValidate;
    for (const auto& s : stages) {
        auto r = shaderc::resolveStage(s.path, options, files);
        EXPECT_TRUE(r.ok) << s.path;
        toValidate.push_back({s.stage, s.path, r.stage});
    }
    return shaderc::validateProgram(toValidate, contract);
}

inline std::string allMessages(const shaderc::ValidatedVariant& v) {
    std::string s;
    for (const auto& d : v.diagnostics) s += shaderc::formatDiagnostic(d, shaderc::ErrorFormat::Gcc);
    return s;
}

}  // namespace prism::test
