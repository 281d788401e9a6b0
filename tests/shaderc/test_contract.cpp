// The binding contract: loading (with file:line and JSON-path errors) and the check
// that rejects attributes and uniforms the runtime never provides.
#include <gtest/gtest.h>

#include <algorithm>

#include "validation_fixture.hpp"

using namespace prism;
using namespace prism::shaderc;

namespace {

const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new test::GlslangEnvironment);

constexpr const char* kContract = R"({
  "attributes": [ { "name": "a_position", "type": "vec3", "location": 0 },
                  { "name": "a_normal", "type": "vec3", "location": 1 } ],
  "uniforms": [ { "name": "u_world", "type": "mat4" },
                { "name": "u_light", "type": "vec3", "array": 4 } ]
})";

Contract contractFrom(const std::string& text) {
    MemoryReader files{{"contract.json", text}};
    auto r = loadContracts({"contract.json"}, files);
    EXPECT_TRUE(r.diagnostics.empty());
    return r.contract;
}

ValidatedVariant validateVertex(const std::string& declarations, const std::string& body,
                                const Contract& contract = contractFrom(kContract)) {
    MemoryReader files{
        {"p.vert", "#version 330 core\n" + declarations + "\nvoid main() { " + body + " }\n"},
        {"p.frag", "#version 330 core\nout vec4 frag;\nvoid main() { frag = vec4(1.0); }\n"},
    };
    return test::validateInMemory(files, {{catalog::Stage::Vertex, "p.vert"}, {catalog::Stage::Fragment, "p.frag"}},
                                  contract);
}

// What a build given no --contract checks against.
Contract builtInContract() {
    MemoryReader none;
    auto r = loadContracts({}, none);
    EXPECT_TRUE(r.diagnostics.empty()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
    return r.contract;
}

}  // namespace

TEST(Contract, LoadsAndSortsAttributesByLocation) {
    auto c = contractFrom(kContract);
    ASSERT_EQ(c.attributes.size(), 2u);
    EXPECT_EQ(c.attributes[0].name, "a_position");
    EXPECT_EQ(c.uniforms[0].name, "u_light");  // sorted by name
    EXPECT_EQ(c.uniforms[0].array, 4);
    EXPECT_EQ(glTypeOf("vec3"), 0x8B51u);
    EXPECT_EQ(glTypeOf("nonsense"), 0u);
}

TEST(Contract, MalformedJsonGivesFileLineColumn) {
    MemoryReader files{{"c.json", "{\n  \"attributes\": [\n    { \"name\": \"a\", }\n  ]\n}\n"}};
    auto r = loadContracts({"c.json"}, files);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].file, "c.json");
    EXPECT_EQ(r.diagnostics[0].line, 3);
}

TEST(Contract, WrongShapeGivesJsonPath) {
    MemoryReader files{{"c.json", R"({"attributes": [{"name": "a_x", "type": "vec3"}], "uniforms": [{"name": 3}]})"}};
    auto r = loadContracts({"c.json"}, files);
    std::string all;
    for (const auto& d : r.diagnostics) all += formatDiagnostic(d, ErrorFormat::Gcc);
    EXPECT_NE(all.find("c.json: error: /attributes/0/location: expected an integer"), std::string::npos) << all;
    EXPECT_NE(all.find("/uniforms/0/name: expected a string"), std::string::npos) << all;
}

TEST(Contract, DuplicateLocationsAreAnError) {
    MemoryReader files{{"c.json", R"({"attributes": [{"name": "a_x", "type": "vec3", "location": 1},
                                                     {"name": "a_y", "type": "vec2", "location": 1}]})"}};
    auto r = loadContracts({"c.json"}, files);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("share location 1"), std::string::npos);
}

TEST(Contract, ShaderWithinTheContractPasses) {
    auto r = validateVertex("in vec3 a_position;\nuniform mat4 u_world;\nuniform vec3 u_light[2];",
                            "gl_Position = u_world * vec4(a_position + u_light[1], 1.0);");
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    ASSERT_EQ(r.reflection.attributes.size(), 1u);
    EXPECT_EQ(r.reflection.attributes[0].location, 0);
}

TEST(Contract, MisspelledAttributeIsRejectedWithSuggestion) {
    auto r = validateVertex("in vec3 a_positon;", "gl_Position = vec4(a_positon, 1.0);");
    ASSERT_FALSE(r.ok);
    auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("p.vert:2:9: error: vertex attribute 'a_positon' is not in the binding contract"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("did you mean 'a_position'?"), std::string::npos) << msg;
}

TEST(Contract, AttributeOfWrongType) {
    auto r = validateVertex("in vec4 a_normal;", "gl_Position = a_normal;");
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("'a_normal' is `vec4` but the contract (contract.json) supplies `vec3`"),
              std::string::npos)
        << test::allMessages(r);
}

TEST(Contract, UnknownUniformIsRejected) {
    auto r = validateVertex("uniform mat4 u_wrold;", "gl_Position = u_wrold[0];");
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("uniform 'u_wrold' is not in the binding contract"), std::string::npos);
}

TEST(Contract, UniformArrayLargerThanTheContractAllows) {
    auto r = validateVertex("uniform vec3 u_light[8];", "gl_Position = vec4(u_light[7], 1.0);");
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("supplies at most 4 elements"), std::string::npos) << test::allMessages(r);
}

TEST(Contract, UniformOfWrongType) {
    auto r = validateVertex("uniform mat3 u_world;", "gl_Position = vec4(u_world[0], 1.0);");
    ASSERT_FALSE(r.ok);
    EXPECT_NE(test::allMessages(r).find("uniform 'u_world' is `mat3` but the contract"), std::string::npos);
}

// Found by the contract_json fuzzer (tests/fuzz/corpus/contract_json/regress-empty-type.json):
// an empty type string skipped the GLSL type check, and names were never checked.
TEST(Contract, EmptyTypeAndNonIdentifierNamesAreErrors) {
    MemoryReader files{{"c.json", R"({"attributes": [{"name": "a_x", "type": "", "location": 0}],
                                      "uniforms": [{"name": "u_a:b", "type": "float"},
                                                   {"name": "", "type": "vec3"}]})"}};
    auto r = loadContracts({"c.json"}, files);
    std::string all;
    for (const auto& d : r.diagnostics) all += formatDiagnostic(d, ErrorFormat::Gcc);
    EXPECT_NE(all.find("/attributes/0/type: expected a GLSL type such as vec3"), std::string::npos) << all;
    EXPECT_NE(all.find("/uniforms/0/name: expected a GLSL identifier such as u_world"), std::string::npos) << all;
    EXPECT_NE(all.find("/uniforms/1/name: expected a GLSL identifier"), std::string::npos) << all;
}

// Found by the contract_json fuzzer (corpus/contract_json/regress-location-past-int.json):
// a location of 2^31 or more wrapped to a negative int and was accepted.
TEST(Contract, LocationPastIntRangeIsAnError) {
    MemoryReader files{{"c.json", R"({"attributes": [{"name": "a_x", "type": "vec3", "location": 2147483648}],
                                      "uniforms": [{"name": "u_a", "type": "float", "array": 4294967296}]})"}};
    auto r = loadContracts({"c.json"}, files);
    std::string all;
    for (const auto& d : r.diagnostics) all += formatDiagnostic(d, ErrorFormat::Gcc);
    EXPECT_NE(all.find("/attributes/0/location: expected a non-negative integer up to 2147483647"), std::string::npos)
        << all;
    EXPECT_NE(all.find("/uniforms/0/array: expected a non-negative integer up to 2147483647"), std::string::npos)
        << all;
}

// Issue 22, item 4: names far from every contract name are the shader's own. A lygia-style
// program (fixture of our own) declares u_resolution, u_time and u_mouse; Prism's contract
// must not reject them.
TEST(Contract, NamesFarFromTheContractAreTheShadersOwn) {
    auto r = validateVertex(
        "in vec3 a_position;\nin vec4 a_tangent;\nuniform vec2 u_resolution;\n"
        "uniform float u_time;\nuniform vec2 u_mouse;",
        "gl_Position = vec4(a_position + a_tangent.xyz, u_time) + vec4(u_resolution, u_mouse);");
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    EXPECT_TRUE(r.diagnostics.empty()) << test::allMessages(r);
}

TEST(Contract, BuiltInContractIsPrismsOwn) {
    const Contract c = builtInContract();
    EXPECT_TRUE(c.builtIn);
    EXPECT_FALSE(c.empty());
    EXPECT_TRUE(c.files.empty());  // nothing for the depfile
    ASSERT_FALSE(c.attributes.empty());
    EXPECT_EQ(c.attributes[0].name, "a_position");
    EXPECT_EQ(c.attributes[0].location, 0);
    EXPECT_TRUE(std::any_of(c.uniforms.begin(), c.uniforms.end(),
                            [](const ContractUniform& u) { return u.name == "u_lightDirection" && u.array == 8; }));
}

// Without --contract a near miss is a warning at the declaration, and the program still
// validates (the name may be the user's own).
TEST(Contract, WithoutAContractANearMissIsAWarningAtItsLine) {
    auto r = validateVertex("in vec3 a_positon;\nuniform mat4 u_wrold;",
                            "gl_Position = u_wrold * vec4(a_positon, 1.0);", builtInContract());
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    const auto msg = test::allMessages(r);
    EXPECT_NE(msg.find("p.vert:2:9: warning: vertex attribute 'a_positon' is not in the binding contract (Prism's "
                       "contract, built into prism-shaderc)"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("(did you mean 'a_position'?)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("p.vert:3:14: warning: uniform 'u_wrold'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(did you mean 'u_world'?)"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("error"), std::string::npos) << msg;
}

TEST(Contract, WithoutAContractFarNamesGiveNoWarning) {
    auto r = validateVertex("in vec3 a_position;\nuniform vec2 u_resolution;\nuniform float u_time;",
                            "gl_Position = vec4(a_position, u_time) + u_resolution.xyxy;", builtInContract());
    EXPECT_TRUE(r.ok) << test::allMessages(r);
    EXPECT_TRUE(r.diagnostics.empty()) << test::allMessages(r);
}
