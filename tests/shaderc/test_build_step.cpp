// The build step's public API (prism/shaderc/build_step.hpp), which the runtime uses in
// place of the tool's private stages: it must hand the stages everything they need, so a
// stage checked through it reports what prism-shaderc reports.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "prism/shaderc/build_step.hpp"

namespace {

namespace sc = prism::shaderc;

const char* kPlainFrag = "#version 330 core\nout vec4 f;\nvoid main() { f = vec4(1.0); }\n";

sc::StageToCheck resolved(const std::string& path, prism::catalog::Stage stage, const sc::Files& files) {
    sc::StageResolution r = sc::resolveStage(path, {}, files);
    EXPECT_TRUE(r.ok) << path;
    return {stage, path, std::move(r.resolved)};
}

// A module's error names the stage that included it: the resolver's include chain
// reaches the validator through FlatStage::record.
TEST(BuildStep, ErrorInAModuleNamesItsIncluder) {
    const std::pair<std::string, std::string> texts[] = {
        {"s/a.vert", "#version 330 core\n#include \"lib/bad.glsl\"\nvoid main() { gl_Position = vec4(0.0); }\n"},
        {"s/lib/bad.glsl", "// bad\nfloat bad() { return vec3(1.0); }\n"},
        {"s/a.frag", kPlainFrag}};
    const sc::Files files = sc::Files::memory(texts);
    const sc::Validator validator;
    const sc::StageToCheck stages[] = {resolved("s/a.vert", prism::catalog::Stage::Vertex, files),
                                       resolved("s/a.frag", prism::catalog::Stage::Fragment, files)};
    const sc::ProgramCheck check = sc::checkProgram(stages, {});
    EXPECT_FALSE(check.ok);
    ASSERT_FALSE(check.messages.empty());
    EXPECT_EQ(check.messages.front().text.rfind("s/lib/bad.glsl:2:", 0), 0u) << check.messages.front().text;
    EXPECT_NE(check.messages.front().text.find("\n  included from s/a.vert:2\n"), std::string::npos)
        << check.messages.front().text;
}

// Loaded from no paths, the contract is Prism's built-in one, against which a near miss
// is a warning (the names may be the user's), as in prism-shaderc without --contract.
TEST(BuildStep, BuiltInContractMakesANearMissAWarning) {
    const sc::ContractLoad builtIn = sc::loadContract({}, sc::Files::memory({}));
    ASSERT_TRUE(builtIn.ok);
    EXPECT_TRUE(builtIn.contract.builtIn);
    const std::pair<std::string, std::string> texts[] = {
        {"s/a.vert", "#version 330 core\nin vec3 a_positon;\nvoid main() { gl_Position = vec4(a_positon, 1.0); }\n"},
        {"s/a.frag", kPlainFrag}};
    const sc::Files files = sc::Files::memory(texts);
    const sc::Validator validator;
    const sc::StageToCheck stages[] = {resolved("s/a.vert", prism::catalog::Stage::Vertex, files),
                                       resolved("s/a.frag", prism::catalog::Stage::Fragment, files)};
    const sc::ProgramCheck check = sc::checkProgram(stages, builtIn.contract);
    EXPECT_TRUE(check.ok);
    ASSERT_EQ(check.messages.size(), 1u);
    EXPECT_FALSE(check.messages.front().error);
    EXPECT_EQ(check.messages.front().text.rfind("s/a.vert:2:9: warning: ", 0), 0u) << check.messages.front().text;
}

TEST(BuildStep, ModuleIdsAreTheCataloguesIdentifiers) {
    EXPECT_EQ(sc::moduleId("toon/quantize.glsl"), "toon__quantize");
    EXPECT_EQ(sc::moduleId("fragment_output.glsl"), "fragment_output");
}

}  // namespace
