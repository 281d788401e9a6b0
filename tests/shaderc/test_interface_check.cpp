// The cross-stage interface check: missing outputs, type, array-size and
// interpolation mismatches, geometry-stage arrayed inputs; errors name both files.
#include <gtest/gtest.h>

#include "validation_fixture.hpp"

using namespace prism;
using namespace prism::shaderc;
using test::validateInMemory;

namespace {

const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new test::GlslangEnvironment);

constexpr catalog::Stage V = catalog::Stage::Vertex, G = catalog::Stage::Geometry, F = catalog::Stage::Fragment;

MemoryReader program(const std::string& vertDecl, const std::string& fragDecl, const std::string& fragUse) {
    return MemoryReader{
        {"s/p.vert", "#version 330 core\nin vec3 a_position;\n" + vertDecl +
                         "\nvoid main() { gl_Position = vec4(a_position, 1.0); }\n"},
        {"s/p.frag", "#version 330 core\nout vec4 frag;\n" + fragDecl + "\nvoid main() { frag = " + fragUse + "; }\n"},
    };
}

}  // namespace

TEST(InterfaceCheck, MatchingInterfacePasses) {
    auto files = program("out vec3 v_normal;", "in vec3 v_normal;", "vec4(v_normal, 1.0)");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    EXPECT_TRUE(r.ok) << test::allMessages(r);
}

TEST(InterfaceCheck, MissingOutputIsAnErrorAtTheInput) {
    auto files = program("", "in vec3 v_normal;", "vec4(v_normal, 1.0)");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("s/p.frag:3:9: error: frag input 'v_normal' is not written by the vert stage (s/p.vert)"),
              std::string::npos)
        << msg;
}

TEST(InterfaceCheck, TypeMismatchNamesBothFiles) {
    auto files = program("out vec4 v_normal;", "in vec3 v_normal;", "vec4(v_normal, 1.0)");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("s/p.frag:3:9: error: frag input 'v_normal' is `smooth vec3` but the vert output is "
                       "`smooth vec4` (type mismatch)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("s/p.vert:3:10: note: the vert output 'v_normal' is declared here"), std::string::npos) << msg;
}

TEST(InterfaceCheck, ArraySizeMismatch) {
    auto files = program("out float v_w[3];", "in float v_w[2];", "vec4(v_w[0])");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("`smooth float[2]` but the vert output is `smooth float[3]`"),
              std::string::npos)
        << test::allMessages(r);
}

TEST(InterfaceCheck, InterpolationMismatch) {
    auto files = program("flat out vec3 v_color;", "in vec3 v_color;", "vec4(v_color, 1.0)");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("is `smooth vec3` but the vert output is `flat vec3` (interpolation qualifier mismatch)"),
              std::string::npos)
        << msg;
}

TEST(InterfaceCheck, NoPerspectiveMismatch) {
    auto files = program("noperspective out vec2 v_uv;", "smooth in vec2 v_uv;", "vec4(v_uv, 0.0, 1.0)");
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("`noperspective vec2`"), std::string::npos) << test::allMessages(r);
}

TEST(InterfaceCheck, GeometryStageInputsAreArraysOfTheVertexOutputs) {
    MemoryReader files{
        {"g.vert",
         "#version 330 core\nin vec3 a_position;\nout vec3 v_n;\n"
         "void main() { v_n = a_position; gl_Position = vec4(a_position, 1.0); }\n"},
        {"g.geom",
         "#version 330 core\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\n"
         "in vec3 v_n[];\nout vec3 v_c;\n"
         "void main() { v_c = v_n[0]; gl_Position = gl_in[0].gl_Position; EmitVertex(); }\n"},
        {"g.frag", "#version 330 core\nin vec3 v_c;\nout vec4 frag;\nvoid main() { frag = vec4(v_c, 1.0); }\n"},
    };
    auto ok = validateInMemory(files, {{V, "g.vert"}, {G, "g.geom"}, {F, "g.frag"}});
    EXPECT_TRUE(ok.ok) << test::allMessages(ok);

    files.add("g.frag", "#version 330 core\nin vec3 v_n;\nout vec4 frag;\nvoid main() { frag = vec4(v_n, 1.0); }\n");
    auto bad = validateInMemory(files, {{V, "g.vert"}, {G, "g.geom"}, {F, "g.frag"}});
    ASSERT_FALSE(bad.ok);
    EXPECT_NE(test::allMessages(bad).find("frag input 'v_n' is not written by the geom stage (g.geom)"),
              std::string::npos)
        << test::allMessages(bad);
}

TEST(InterfaceCheck, ErrorInsideAModuleIsReportedAtTheModuleLineWithChain) {
    MemoryReader files{
        {"mods/helper.glsl", "// Provides: a helper.\nvec3 helper(vec3 x) {\n    return x * undefinedThing;\n}\n"},
        {"s/p.vert",
         "#version 330 core\n#include <helper.glsl>\nin vec3 a_position;\n"
         "void main() { gl_Position = vec4(helper(a_position), 1.0); }\n"},
        {"s/p.frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n"},
    };
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}}, {}, {"mods"});
    ASSERT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    const auto& d = r.diagnostics.front();
    EXPECT_EQ(d.file, "mods/helper.glsl");
    EXPECT_EQ(d.line, 3);
    EXPECT_EQ(d.column, 16);  // found from the token glslang names
    ASSERT_EQ(d.includedFrom.size(), 1u);
    EXPECT_EQ(d.includedFrom[0].file, "s/p.vert");
    EXPECT_EQ(d.includedFrom[0].line, 2);
}

TEST(InterfaceCheck, FollowOnErrorsOnOneLineBecomeANote) {
    MemoryReader files{
        {"s/p.vert",
         "#version 330 core\nin vec3 a_position;\n"
         "void main() { vec3 y = vec2(1.0) + nope; gl_Position = vec4(y, 1.0); }\n"},
        {"s/p.frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n"},
    };
    auto r = validateInMemory(files, {{V, "s/p.vert"}, {F, "s/p.frag"}});
    ASSERT_FALSE(r.ok);
    int errorsOnLine3 = 0;
    for (const auto& d : r.diagnostics) errorsOnLine3 += d.severity == Severity::Error && d.line == 3;
    EXPECT_EQ(errorsOnLine3, 1) << test::allMessages(r);
    EXPECT_NE(test::allMessages(r).find("follow-on error"), std::string::npos) << test::allMessages(r);
}

TEST(InterfaceCheck, ComputeNeedsVersion430) {
    MemoryReader files{{"c.comp", "#version 330 core\nlayout(local_size_x = 1) in;\nvoid main() {}\n"}};
    auto r = validateInMemory(files, {{catalog::Stage::Compute, "c.comp"}});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("compute shaders need GLSL 430"), std::string::npos);
    files.add("c.comp", "#version 430 core\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
    EXPECT_TRUE(validateInMemory(files, {{catalog::Stage::Compute, "c.comp"}}).ok);
}
