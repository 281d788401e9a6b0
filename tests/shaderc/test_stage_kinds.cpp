// Tessellation programs and interfaces matched as GL matches them (issue 24, items 2 and 4):
// per-vertex arrays between vert, tesc and tese, patch variables, matching by explicit
// location whatever the names, and explicit attribute locations against the contract.
#include <gtest/gtest.h>

#include <map>

#include "validation_fixture.hpp"

using namespace prism;
using namespace prism::shaderc;
using test::validateInMemory;

namespace {

const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new test::GlslangEnvironment);

constexpr catalog::Stage V = catalog::Stage::Vertex, TC = catalog::Stage::TessControl,
                         TE = catalog::Stage::TessEvaluation, F = catalog::Stage::Fragment;

// vert -> tesc -> tese -> frag, with `tescOut` / `teseIn` the declarations between tesc and tese.
MemoryReader tessProgram(const std::string& tescOut, const std::string& tescWrite, const std::string& teseIn,
                         const std::string& teseRead) {
    return MemoryReader{
        {"t/p.vert", "#version 400 core\nin vec3 a_position;\nout vec3 v_pos;\nvoid main() { v_pos = a_position; }\n"},
        {"t/p.tesc", "#version 400 core\nlayout(vertices = 3) out;\nin vec3 v_pos[];\n" + tescOut +
                         "\nvoid main() {\n    " + tescWrite +
                         ";\n    gl_TessLevelOuter[0] = 1.0;\n    gl_TessLevelInner[0] = 1.0;\n}\n"},
        {"t/p.tese", "#version 400 core\nlayout(triangles) in;\n" + teseIn +
                         "\nout vec3 te_pos;\nvoid main() {\n"
                         "    te_pos = " +
                         teseRead + ";\n    gl_Position = vec4(te_pos, 1.0);\n}\n"},
        {"t/p.frag", "#version 400 core\nin vec3 te_pos;\nout vec4 frag;\nvoid main() { frag = vec4(te_pos, 1.0); }\n"},
    };
}

const std::vector<test::InMemoryStage> kTessStages = {
    {V, "t/p.vert"}, {TC, "t/p.tesc"}, {TE, "t/p.tese"}, {F, "t/p.frag"}};

MemoryReader located(const std::string& vertDecl, const std::string& vertWrite, const std::string& fragDecl,
                     const std::string& fragRead) {
    return MemoryReader{
        {"l/p.vert", "#version 410 core\nin vec3 a_position;\n" + vertDecl + "\nvoid main() {\n    " + vertWrite +
                         ";\n    gl_Position = vec4(a_position, 1.0);\n}\n"},
        {"l/p.frag", "#version 410 core\nout vec4 frag;\n" + fragDecl + "\nvoid main() { frag = " + fragRead + "; }\n"},
    };
}

}  // namespace

TEST(StageKinds, TessellationProgramWithPerVertexArraysAndPatchVariablesPasses) {
    auto files =
        tessProgram("out vec3 tc_pos[];\npatch out float tc_w;", "tc_pos[gl_InvocationID] = v_pos[0]; tc_w = 1.0",
                    "in vec3 tc_pos[];\npatch in float tc_w;", "tc_pos[0] * tc_w");
    auto r = validateInMemory(files, kTessStages);
    EXPECT_TRUE(r.ok) << test::allMessages(r);
}

namespace {

// Validates `files` as the tessellation program and expects it to fail with `message`.
void expectTessError(const MemoryReader& files, const std::string& message) {
    auto r = validateInMemory(files, kTessStages);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find(message), std::string::npos) << test::allMessages(r);
}

}  // namespace

TEST(StageKinds, FragmentStageIsCheckedAgainstTheEvaluationStageNotTheVertexStage) {
    auto files =
        tessProgram("out vec3 tc_pos[];", "tc_pos[gl_InvocationID] = v_pos[0]", "in vec3 tc_pos[];", "tc_pos[0]");
    files.add("t/p.frag",
              "#version 400 core\nin vec3 v_pos;\nout vec4 frag;\nvoid main() { frag = vec4(v_pos, 1.0); }\n");
    expectTessError(files, "t/p.frag:2:9: error: frag input 'v_pos' is not written by the tese stage");
}

TEST(StageKinds, TessElementTypeClashBetweenControlAndEvaluation) {
    expectTessError(
        tessProgram("out vec3 tc_pos[];", "tc_pos[gl_InvocationID] = v_pos[0]", "in vec4 tc_pos[];", "tc_pos[0].xyz"),
        "tese input 'tc_pos' is `smooth vec4` but the tesc output is `smooth vec3` (type mismatch)");
}

TEST(StageKinds, PatchQualifierMustMatch) {
    expectTessError(
        tessProgram("patch out vec3 tc_center;", "tc_center = v_pos[0]", "in vec3 tc_center[];", "tc_center[0]"),
        "(patch qualifier mismatch)");
}

TEST(InterfaceLocations, SameLocationMatchesWhateverTheNames) {
    auto files = located("layout(location = 2) out vec2 v_texcoord;", "v_texcoord = a_position.xy",
                         "layout(location = 2) in vec2 in_uv;", "vec4(in_uv, 0.0, 1.0)");
    auto r = validateInMemory(files, {{V, "l/p.vert"}, {F, "l/p.frag"}});
    EXPECT_TRUE(r.ok) << test::allMessages(r);
}

TEST(InterfaceLocations, TypeCheckAppliesToThePairMatchedByLocation) {
    auto files = located("layout(location = 0) out vec2 v_texcoord;", "v_texcoord = a_position.xy",
                         "layout(location = 0) in vec3 in_uv;", "vec4(in_uv, 1.0)");
    auto r = validateInMemory(files, {{V, "l/p.vert"}, {F, "l/p.frag"}});
    ASSERT_FALSE(r.ok);
    const auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("frag input 'in_uv' (location 0) is `smooth vec3` but the vert output 'v_texcoord' "
                       "(location 0) is `smooth vec2` (type mismatch)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("note: the vert output 'v_texcoord' is declared here"), std::string::npos) << msg;
}

TEST(InterfaceLocations, InterpolationCheckAppliesToThePairMatchedByLocation) {
    auto files = located("layout(location = 1) flat out vec2 v_a;", "v_a = a_position.xy",
                         "layout(location = 1) in vec2 in_b;", "vec4(in_b, 0.0, 1.0)");
    auto r = validateInMemory(files, {{V, "l/p.vert"}, {F, "l/p.frag"}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("(interpolation qualifier mismatch)"), std::string::npos)
        << test::allMessages(r);
}

TEST(InterfaceLocations, SameNameAtAnotherLocationDoesNotMatch) {
    auto files = located("layout(location = 1) out vec2 v_uv;", "v_uv = a_position.xy",
                         "layout(location = 0) in vec2 v_uv;", "vec4(v_uv, 0.0, 1.0)");
    auto r = validateInMemory(files, {{V, "l/p.vert"}, {F, "l/p.frag"}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("frag input 'v_uv' (location 0) is not written by the vert stage"),
              std::string::npos)
        << test::allMessages(r);
}

TEST(InterfaceLocations, WithoutLocationsNamesStillMatch) {
    auto files = located("out vec2 v_uv;", "v_uv = a_position.xy", "in vec2 v_uv;", "vec4(v_uv, 0.0, 1.0)");
    auto r = validateInMemory(files, {{V, "l/p.vert"}, {F, "l/p.frag"}});
    EXPECT_TRUE(r.ok) << test::allMessages(r);
}

namespace {

shaderc::ValidatedVariant withContract(const std::string& attributeDecl, const std::string& scale = "1.0") {
    MemoryReader files{
        {"c/p.vert", "#version 410 core\n" + attributeDecl + "\nvoid main() { gl_Position = vec4(a_position * " +
                         scale + ", 1.0); }\n"},
        {"c/p.frag", "#version 410 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n"},
        {"c/contract.json", R"({"attributes": [{"name": "a_position", "type": "vec3", "location": 0}],
                                "uniforms": []})"},
    };
    auto contract = loadContracts({"c/contract.json"}, files);
    EXPECT_TRUE(contract.diagnostics.empty());
    return validateInMemory(files, {{V, "c/p.vert"}, {F, "c/p.frag"}}, contract.contract);
}

}  // namespace

TEST(ContractLocations, ExplicitLocationContradictingTheContractNamesBoth) {
    auto r = withContract("layout(location = 3) in vec3 a_position;");
    ASSERT_FALSE(r.ok);
    const auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("c/p.vert:2:30: error: vertex attribute 'a_position' is at layout(location = 3) but the "
                       "binding contract puts it at location 0"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("c/contract.json /attributes/0: note: the contract's entry: 'a_position' at location 0"),
              std::string::npos)
        << msg;
}

TEST(ContractLocations, ExplicitLocationAgreeingWithTheContractPasses) {
    auto r = withContract("layout(location = 0) in vec3 a_position;");
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    ASSERT_EQ(r.reflection.attributes.size(), 1u);
    EXPECT_EQ(r.reflection.attributes[0].location, 0);
}

TEST(ContractLocations, CatalogueRecordsTheExplicitLocationOfAnAttributeOutsideTheContract) {
    auto r = withContract("in vec3 a_position;\nlayout(location = 5) in float a_weight;", "a_weight");
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    std::map<std::string, int> locations;
    for (const auto& a : r.reflection.attributes) locations[a.name] = a.location;
    EXPECT_EQ(locations["a_position"], 0);
    EXPECT_EQ(locations["a_weight"], 5);
}
