// The Vulkan client links stages as the Vulkan API does (issue 36): GLSL ES compute stages
// as glslc takes them; programs without a fragment stage; each stage linked alone (blocks
// that only share a name are no error, ray-tracing stages are one program); stages meet by
// location (mesh to fragment included), descriptors by set and binding, ray-tracing data by
// location, each mismatch an error at one declaration with a note at the other; and block
// layout rules from the stage's own #extension lines. The fixtures are the reference corpus's
// vk_* cases (test_reference_corpus.cpp checks them against glslc); here the exact messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

const fs::path kCorpus = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/reference_corpus";

prism::test::ToolRun checkVulkan(const std::string& caseFolder, const std::string& stages) {
    return runShaderc("--client vulkan --check --cache-dir none " + stages, (kCorpus / caseFolder).string());
}

TEST(VulkanRules, EsComputeStagesNeedGlslEs310AndTheAdviceNamesTheProfile) {
    EXPECT_EQ(checkVulkan("vk_es_compute", "double.comp").exitCode, 0);
    const auto old = checkVulkan("vk_es_compute_too_old", "double.comp");
    EXPECT_EQ(old.exitCode, 1) << old.output;
    EXPECT_NE(old.output.find("double.comp:1:1: error: compute shaders need GLSL ES 310 or newer, this stage is 300 "
                              "es; add `#version 310 es`"),
              std::string::npos)
        << old.output;
    EXPECT_EQ(old.output.find("430"), std::string::npos) << old.output;
}

TEST(VulkanRules, VertexOnlyAndMeshOnlyPipelinesNeedNoFragmentStageUnderVulkanOnly) {
    EXPECT_EQ(checkVulkan("vk_depth_only", "shadow.vert").exitCode, 0);
    const auto mesh = checkVulkan("vk_mesh_only", "../../vulkan/mesh/meshlet.task ../../vulkan/mesh/meshlet.mesh");
    EXPECT_EQ(mesh.exitCode, 0) << mesh.output;
    // The OpenGL client keeps its rule: GLSL ES 3.00 and WebGL 2 programs must have one.
    ScratchDir dir("vulkan-rules-gl");
    dir.write("s/shadow.vert", "#version 330 core\nin vec3 a;\nvoid main() { gl_Position = vec4(a, 1.0); }\n");
    const auto gl = runShaderc("--check --cache-dir none s", dir.str());
    EXPECT_EQ(gl.exitCode, 1) << gl.output;
    EXPECT_NE(gl.output.find("s/shadow.vert: error: shader 'shadow' has no fragment stage: expected s/shadow.frag"),
              std::string::npos)
        << gl.output;
}

TEST(VulkanRules, BlocksThatOnlyShareANameAreNotLinked) {
    const auto run = checkVulkan("vk_blocks_share_a_name", "lit.vert lit.frag");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    const auto rt = checkVulkan("vk_ray_tracing_program", "trace.rgen trace.rchit trace.rmiss");
    EXPECT_EQ(rt.exitCode, 0) << rt.output;
    EXPECT_EQ(rt.output.find("link"), std::string::npos) << rt.output;
}

TEST(VulkanRules, IncompatibleDescriptorsOnOneBindingAreAnErrorAtBothDeclarations) {
    const auto run = checkVulkan("vk_descriptor_mismatch", "lit.vert lit.frag");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("lit.frag:5:48: error: frag stage declares set 0, binding 0 ('albedo') as `sampler2D` "
                              "but the vert stage declares it as `uniform buffer`; make both declarations agree\n"
                              "lit.vert:5:38: note: the vert stage's declaration is here"),
              std::string::npos)
        << run.output;
}

TEST(VulkanRules, RayPayloadTypesThatDifferAreAnErrorAtBothLines) {
    const auto run = checkVulkan("vk_payload_mismatch", "trace.rgen trace.rchit trace.rmiss");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("trace.rmiss:4:43: error: rmiss stage declares the ray payload at location 0 "
                              "('hitValue') as `vec4` but the rgen stage declares it as `vec3`; make both declarations "
                              "agree\ntrace.rgen:7:41: note: the rgen stage's declaration is here"),
              std::string::npos)
        << run.output;
}

TEST(VulkanRules, RayPayloadStructsMatchByMembersWhateverTheirNames) {
    ScratchDir dir("vulkan-rules-payload-structs");
    const std::string head = "#version 460\n#extension GL_EXT_ray_tracing : require\n";
    dir.write("s/trace.rgen", head +
                                  "layout(set = 0, binding = 0) uniform accelerationStructureEXT topLevel;\n"
                                  "struct Payload { vec3 color; float distance; };\n"
                                  "layout(location = 0) rayPayloadEXT Payload payload;\n"
                                  "void main() { traceRayEXT(topLevel, 0u, 0xffu, 0u, 0u, 0u, vec3(0.0), 0.0, "
                                  "vec3(0.0, 0.0, 1.0), 1.0, 0); }\n");
    dir.write("s/trace.rmiss", head +
                                   "struct MissData { vec3 sky; float t; };\n"
                                   "layout(location = 0) rayPayloadInEXT MissData miss;\n"
                                   "void main() { miss.sky = vec3(0.5); miss.t = -1.0; }\n");
    const auto same = runShaderc("--client vulkan --check --cache-dir none s", dir.str());
    EXPECT_EQ(same.exitCode, 0) << same.output;
    dir.write("s/trace.rmiss", head +
                                   "struct MissData { vec4 sky; float t; };\n"
                                   "layout(location = 0) rayPayloadInEXT MissData miss;\n"
                                   "void main() { miss.sky = vec4(0.5); miss.t = -1.0; }\n");
    const auto differ = runShaderc("--client vulkan --check --cache-dir none s", dir.str());
    EXPECT_EQ(differ.exitCode, 1) << differ.output;
    EXPECT_NE(differ.output.find("s/trace.rmiss:4:"), std::string::npos) << differ.output;
    EXPECT_NE(differ.output.find("as `struct { vec4; float; }` but the rgen stage declares it as `struct { vec3; "
                                 "float; }`"),
              std::string::npos)
        << differ.output;
}

TEST(VulkanRules, MeshOutputsMeetFragmentInputsByLocationPerPrimitiveOnesIncluded) {
    const auto run = checkVulkan("vk_mesh_interface_mismatch", "tint.mesh tint.frag");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("tint.frag:5:46: error: frag input 'p_tint' (location 1) is `perprimitiveEXT vec3` but "
                              "the mesh output is `perprimitiveEXT vec4` (type mismatch); make both declarations "
                              "agree\ntint.mesh:7:47: note: the mesh output 'p_tint' is declared here"),
              std::string::npos)
        << run.output;
    // Without perprimitiveEXT on the fragment input, the qualifier is what differs.
    ScratchDir dir("vulkan-rules-mesh");
    dir.write("s/tint.mesh", prism::test::readFile(kCorpus / "vk_mesh_interface_mismatch/tint.mesh"));
    dir.write("s/tint.frag",
              "#version 450\nlayout(location = 0) in vec3 v_color;\nlayout(location = 1) flat in vec4 p_tint;\n"
              "layout(location = 0) out vec4 o_color;\nvoid main() { o_color = vec4(v_color, 1.0) * p_tint; }\n");
    const auto flat = runShaderc("--client vulkan --check --cache-dir none s", dir.str());
    EXPECT_EQ(flat.exitCode, 1) << flat.output;
    EXPECT_NE(flat.output.find("s/tint.frag:3:"), std::string::npos) << flat.output;
    EXPECT_NE(flat.output.find("(perprimitiveEXT qualifier mismatch)"), std::string::npos) << flat.output;
}

TEST(VulkanRules, BlocksOfTwoNamesMeetByLocationAndMatchByTheirMembersTypes) {
    EXPECT_EQ(checkVulkan("vk_blocks_meet_by_location", "lit.vert lit.frag").exitCode, 0);
    ScratchDir dir("vulkan-rules-block-members");
    dir.write("s/lit.vert", prism::test::readFile(kCorpus / "vk_blocks_meet_by_location/lit.vert"));
    dir.write("s/lit.frag",
              "#version 450\nlayout(location = 0) in VertexInput {\n    vec4 color;\n    vec3 uv;\n} vertexInput;\n"
              "layout(location = 0) out vec4 o_color;\nvoid main() { o_color = vertexInput.color; }\n");
    const auto run = runShaderc("--client vulkan --check --cache-dir none s", dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("s/lit.frag:2:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("(type mismatch)"), std::string::npos) << run.output;
}

TEST(VulkanRules, ScalarBlockLayoutExtensionSelectsTheValidatorsScalarRules) {
    const auto run = checkVulkan("vk_scalar_block_layout", "scatter.comp");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("SPIRV-Tools"), std::string::npos) << run.output;
}

}  // namespace
