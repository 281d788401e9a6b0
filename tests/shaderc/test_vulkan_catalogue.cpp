// A Vulkan-client catalogue (prism_add_shaders(... CLIENT vulkan), tests/shaderc/CMakeLists.txt)
// read back through prism/catalog: each stage's SPIR-V words, and the reflection of the
// `lit` program (push constants, two sets, a specialisation constant, vertex inputs) as a
// golden text (baseResults/vulkan_reflection.txt; PRISM_UPDATE_BASELINES=1 rewrites it).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "baseline.hpp"
#include "prism_vulkan_test_shaders.hpp"

namespace {

using prism::catalog::ResourceKind;
using prism::catalog::Stage;
namespace shaders = prism_test::vulkan_shaders;

const prism::catalog::Variant& onlyVariant(std::string_view name) {
    const auto* s = prism::catalog::findShader(shaders::kCatalog, name);
    EXPECT_NE(s, nullptr) << name;
    return s->variants[0];
}

std::string hex(std::uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%x", v);
    return text;
}

// The reflection as the runtime sees it, one line a record.
std::string describe(const prism::catalog::Variant& v) {
    std::ostringstream out;
    for (const auto& st : v.stages) out << "stage " << prism::catalog::stageName(st.stage) << "\n";
    for (const auto& a : v.attributes)
        out << "input " << a.name << " location " << a.location << " type " << hex(a.glType) << "\n";
    for (const auto& r : v.resources) {
        out << "resource " << r.name << " set " << r.set << " binding " << r.binding << " "
            << prism::catalog::resourceKindName(r.kind) << " size " << r.size << " array " << r.arraySize << "\n";
        for (const auto& m : r.members)
            out << "  member " << m.name << " offset " << m.offset << " type " << hex(m.glType) << " array "
                << m.arraySize << "\n";
    }
    for (const auto& p : v.pushConstants)
        out << "push " << p.name << " offset " << p.offset << " size " << p.size << " type " << hex(p.glType) << "\n";
    for (const auto& c : v.specConstants)
        out << "spec " << c.name << " id " << c.id << " type " << hex(c.glType) << " default " << hex(c.defaultBits)
            << "\n";
    return out.str();
}

TEST(VulkanCatalogue, StagesCarryTheirSpirvWords) {
    EXPECT_EQ(shaders::kCatalog.targetEnv, "vulkan1.2");
    for (const auto& shader : shaders::kCatalog.shaders)
        for (const auto& st : shader.variants[0].stages) {
            ASSERT_GT(st.spirv.size(), 5u) << shader.name;
            EXPECT_EQ(st.spirv[0], 0x07230203u) << shader.name;  // SPIR-V's magic number
            EXPECT_EQ(st.spirv[1], 0x00010500u) << shader.name;  // SPIR-V 1.5, Vulkan 1.2's
            EXPECT_FALSE(st.chunks.empty()) << "the flattened GLSL stays beside the words";
        }
    const auto& scene = onlyVariant("scene");
    ASSERT_EQ(scene.stages.size(), 3u);
    EXPECT_EQ(scene.stages[0].stage, Stage::RayGen);
    EXPECT_EQ(scene.stages[1].stage, Stage::ClosestHit);
    EXPECT_EQ(scene.stages[2].stage, Stage::Miss);
}

TEST(VulkanCatalogue, LitReflection) {
    const auto& lit = onlyVariant("lit");
    ASSERT_EQ(lit.attributes.size(), 3u);
    EXPECT_EQ(lit.attributes[2].name, "a_uv");
    EXPECT_EQ(lit.attributes[2].location, 3);
    ASSERT_EQ(lit.pushConstants.size(), 3u);
    EXPECT_EQ(lit.pushConstants[1].offset, 64u);  // after mat4 model
    EXPECT_EQ(lit.pushConstants[1].size, 16u);
    EXPECT_EQ(lit.pushConstants[2].offset, 80u);
    ASSERT_EQ(lit.resources.size(), 3u);
    EXPECT_EQ(lit.resources[0].set, 0u);
    EXPECT_EQ(lit.resources[0].size, 76u);  // mat4 + vec3 (std140), its declared size
    EXPECT_EQ(lit.resources[1].set, 1u);
    EXPECT_EQ(lit.resources[1].kind, ResourceKind::CombinedImageSampler);
    EXPECT_EQ(lit.resources[2].binding, 2u);
    ASSERT_EQ(lit.resources[0].members.size(), 2u);
    EXPECT_EQ(lit.resources[0].members[1].offset, 64u);  // vec3 after mat4 (std140)
    EXPECT_TRUE(lit.resources[1].members.empty());       // a sampler has none
    // The SPIR-V's vertex inputs are the shader's own, as in `attributes`.
    ASSERT_EQ(lit.spirvInputs.size(), lit.attributes.size());
    EXPECT_EQ(lit.spirvInputs.data(), lit.attributes.data());
    ASSERT_EQ(lit.specConstants.size(), 1u);
    EXPECT_EQ(lit.specConstants[0].id, 7u);
    float ambient = 0;
    std::memcpy(&ambient, &lit.specConstants[0].defaultBits, sizeof ambient);
    EXPECT_EQ(ambient, 0.125f);
    prism::test::expectMatchesBaseline(describe(lit), "vulkan_reflection.txt");
}

TEST(VulkanCatalogue, ComputeSpecConstantsWithTheirDefaults) {
    const auto& blur = onlyVariant("blur");
    ASSERT_EQ(blur.specConstants.size(), 4u) << describe(blur);
    EXPECT_EQ(blur.specConstants[0].name, "RADIUS");
    EXPECT_EQ(blur.specConstants[0].defaultBits, 4u);
    EXPECT_EQ(blur.specConstants[2].name, "CLAMP");
    EXPECT_EQ(blur.specConstants[2].defaultBits, 1u);
    EXPECT_EQ(blur.specConstants[3].id, 3u);  // local_size_x_id
    ASSERT_EQ(blur.resources.size(), 2u);
    EXPECT_EQ(blur.resources[1].kind, ResourceKind::StorageImage);
}

}  // namespace
