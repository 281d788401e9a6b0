// The Vulkan usage example of docs/targets.md, compiled and run against a catalogue that
// prism_add_shaders(... TARGETS gl es300 spirv) generated: fill Phong's uniform block from the
// spirv target's reflection, and find the es300 text and the SPIR-V words beside the gl text.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "prism/targets_catalogue.hpp"

namespace {

// [vulkan-usage]
// One std140 uniform buffer for a variant's spirv target: every member written at its
// reflected offset (here every float component set to `fill`; an application writes its values).
std::vector<std::byte> fillUniformBlock(const prism::catalog::Resource& block, float fill) {
    std::vector<std::byte> buffer(block.size);
    for (const auto& member : block.members) {
        const std::size_t floats = member.glType == 0x8B5C ? 16 : member.glType == 0x8B51 ? 3 : 1;  // mat4, vec3
        for (std::size_t i = 0; i < floats && member.offset + 4 * (i + 1) <= block.size; ++i)
            std::memcpy(buffer.data() + member.offset + 4 * i, &fill, sizeof fill);
    }
    return buffer;  // vkCmdUpdateBuffer / a mapped VkBuffer at (block.set, block.binding)
}
// [vulkan-usage]

const prism::catalog::Variant& phong() {
    const auto& shader = prism::targets_catalogue::shaderInfo(prism::targets_catalogue::ShaderId::phong);
    const auto* v = prism::catalog::findVariant(
        shader, {{"BLINN", "1"}, {"FOG", "0"}, {"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "1"}});
    EXPECT_NE(v, nullptr);
    return *v;
}

}  // namespace

TEST(TargetsCatalogue, VulkanUsageFillsTheUniformBlockFromTheReflection) {
    const auto& v = phong();
    std::vector<const prism::catalog::Resource*> blocks;
    for (const auto& r : v.resources)
        if (r.kind == prism::catalog::ResourceKind::UniformBuffer) blocks.push_back(&r);
    ASSERT_EQ(blocks.size(), 1u);
    const auto& block = *blocks[0];
    EXPECT_EQ(std::string(block.name), "gl_DefaultUniformBlock");
    const auto buffer = fillUniformBlock(block, 0.5f);
    ASSERT_EQ(buffer.size(), block.size);
    // Every member lies inside the block and after the previous one (std140 order).
    std::uint32_t previous = 0;
    for (const auto& m : block.members) {
        EXPECT_LT(m.offset, block.size) << m.name;
        EXPECT_GE(m.offset, previous) << m.name;
        previous = m.offset;
        float read = 0;
        std::memcpy(&read, buffer.data() + m.offset, sizeof read);
        EXPECT_EQ(read, 0.5f) << m.name;
    }
    for (const auto& name : {"u_world", "u_view", "u_projection", "u_color"}) {
        bool found = false;
        for (const auto& m : block.members) found = found || m.name == name;
        EXPECT_TRUE(found) << name << " is not in the block";
    }
}

TEST(TargetsCatalogue, EveryTargetSitsBesideTheGlText) {
    const auto& v = phong();
    ASSERT_EQ(v.stages.size(), 2u);
    ASSERT_EQ(v.es300Stages.size(), 2u);
    EXPECT_EQ(prism::catalog::joinChunks(v.es300Stages[1].chunks).rfind("#version 300 es\n", 0), 0u);
    EXPECT_EQ(prism::catalog::joinChunks(v.stages[1].chunks).rfind("#version 330 core\n", 0), 0u);
    for (const auto& stage : v.stages) {
        ASSERT_FALSE(stage.spirv.empty()) << prism::catalog::stageName(stage.stage);
        EXPECT_EQ(stage.spirv[0], 0x07230203u);  // SPIR-V's magic number
    }
    ASSERT_FALSE(v.spirvInputs.empty());
    EXPECT_EQ(std::string(v.spirvInputs[0].name), "a_position");
    EXPECT_EQ(v.spirvInputs[0].location, 0);
}
