// prism::vk::UniformBlock: members written by name at the reflected std140 offsets of the
// catalogue's spirv target; unknown names and wrong types refused. No Vulkan device needed.
#include <gtest/gtest.h>

#include <cstring>

#include "prism/shaders.hpp"
#include "prism/vk/uniform_block.hpp"

namespace {

const prism::catalog::Resource& phongBlock() {
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const auto* v = prism::catalog::findVariant(phong, {{"DIRECTIONAL_LIGHTS", "2"}, {"POINT_LIGHTS", "0"}});
    if (v == nullptr || v->resources.empty()) throw std::runtime_error("phong has no spirv target here");
    return v->resources[0];
}

const prism::catalog::BlockMember& member(const prism::catalog::Resource& block, std::string_view name) {
    for (const auto& m : block.members)
        if (m.name == name) return m;
    throw std::runtime_error("no member " + std::string(name));
}

template <class T>
T readAt(const prism::vk::UniformBlock& b, std::size_t offset) {
    T value;
    std::memcpy(&value, b.bytes().data() + offset, sizeof value);
    return value;
}

TEST(UniformBlock, WritesEachMemberAtItsReflectedOffset) {
    const auto& block = phongBlock();
    prism::vk::UniformBlock b(block, "phong");
    ASSERT_EQ(b.bytes().size(), block.size);
    b.set("u_shininess", 32.0f);
    b.set(prism::shaders::contract::u_color, glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
    const std::vector<glm::vec3> dirs{{1, 2, 3}, {4, 5, 6}};
    b.set("u_lightDirection", std::span<const glm::vec3>(dirs));
    glm::mat3 normal(1.0f);
    normal[1][2] = 7.0f;
    b.set("u_normal", normal);
    EXPECT_EQ(readAt<float>(b, member(block, "u_shininess").offset), 32.0f);
    EXPECT_EQ(readAt<float>(b, member(block, "u_color").offset + 12), 0.4f);
    const std::size_t dir = member(block, "u_lightDirection").offset;
    EXPECT_EQ(readAt<float>(b, dir + 16 + 8), 6.0f) << "std140: array elements 16 bytes apart";
    EXPECT_EQ(readAt<float>(b, member(block, "u_normal").offset + 16 + 8), 7.0f) << "mat3 columns 16 bytes apart";
    EXPECT_TRUE(b.hasUniform("u_lightDirection[1]"));
    EXPECT_FALSE(b.hasUniform("u_lightDirection[2]"));
}

TEST(UniformBlock, AnInjectedOffsetFaultMovesEveryMember) {
    const auto& block = phongBlock();
    prism::vk::UniformBlock b(block, "phong", 4);
    b.set("u_shininess", 32.0f);
    EXPECT_EQ(readAt<float>(b, member(block, "u_shininess").offset + 4), 32.0f);
    EXPECT_EQ(readAt<float>(b, member(block, "u_shininess").offset), 0.0f);
}

TEST(UniformBlock, RefusesUnknownNamesAndWrongTypes) {
    prism::vk::UniformBlock b(phongBlock(), "phong");
    try {
        b.set("u_shinines", 1.0f);
        FAIL() << "an unknown name was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'u_shininess'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(b.set("u_shininess", glm::vec3(1.0f)), std::invalid_argument);
    EXPECT_THROW(b.set("u_lightDirection[5]", glm::vec3(1.0f)), std::invalid_argument);
    // A typed handle of a uniform this variant lacks is a no-op, as in prism::gl::Program.
    EXPECT_NO_THROW(b.set(prism::shaders::contract::u_fogDensity, 0.5f));
}

}  // namespace
