// The generated C++ structs of a Vulkan-client catalogue's blocks (block_structs.hpp): a
// push-constant block filled through its struct holds each value at the offset the stage's
// SPIR-V declares (OpMemberDecorate ... Offset, read from the catalogue's own words), and the
// struct of a scalar-layout storage block matches its fixed part. The static_asserts in the
// generated header make a drifted layout a compile error; this file compiling is that check.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <string>

#include "prism_vulkan_test_shaders.hpp"

namespace {

namespace shaders = prism_test::vulkan_shaders;
namespace blocks = prism_test::vulkan_shaders::blocks;

std::string spirvLiteral(std::span<const std::uint32_t> words) {
    std::string s;
    for (auto w : words)
        for (int b = 0; b < 4; ++b) {
            const char c = static_cast<char>((w >> (8 * b)) & 0xFF);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

// Member name -> offset of the struct type named `typeName` in one module (SPIR-V section 3:
// OpName 5, OpMemberName 6, OpMemberDecorate 72, decoration Offset 35).
std::map<std::string, std::uint32_t> spirvMemberOffsets(std::span<const std::uint32_t> words,
                                                        const std::string& typeName) {
    std::map<std::uint32_t, std::string> typeNames;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> memberNames;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> offsets;
    for (std::size_t at = 5; at < words.size() && (words[at] >> 16) > 0; at += words[at] >> 16) {
        const std::uint32_t op = words[at] & 0xFFFF;
        const auto a = words.subspan(at + 1, (words[at] >> 16) - 1);
        if (op == 5) typeNames[a[0]] = spirvLiteral(a.subspan(1));
        if (op == 6) memberNames[{a[0], a[1]}] = spirvLiteral(a.subspan(2));
        if (op == 72 && a[2] == 35) offsets[{a[0], a[1]}] = a[3];
    }
    std::map<std::string, std::uint32_t> out;
    for (const auto& [key, offset] : offsets)
        if (typeNames[key.first] == typeName) out[memberNames[key]] = offset;
    return out;
}

const prism::catalog::StageSource& layoutsStage(std::string_view shader, prism::catalog::Stage stage) {
    const auto* s = prism::catalog::findShader(shaders::kCatalog, shader);
    EXPECT_NE(s, nullptr);
    for (const auto& st : s->variants[0].stages)
        if (st.stage == stage) return st;
    throw std::runtime_error("no such stage");
}

template <class T>
T readBlockAt(const std::byte* bytes, std::uint32_t offset) {
    T value;
    std::memcpy(&value, bytes + offset, sizeof value);
    return value;
}

TEST(BlockStructs, PushConstantsLieAtTheSpirvOffsets) {
    blocks::layouts::Push push{};
    push.model = glm::mat4(2.0f);
    push.model[3] = glm::vec4(1, 2, 3, 1);
    push.vertices = 0x1122334455667788ull;  // a VkDeviceAddress
    push.materialIndex = 7;
    push.exposure = 1.5f;
    const auto offsets = spirvMemberOffsets(layoutsStage("layouts", prism::catalog::Stage::Vertex).spirv, "Push");
    ASSERT_EQ(offsets.size(), 4u);
    const auto* bytes = reinterpret_cast<const std::byte*>(&push);
    EXPECT_EQ(readBlockAt<float>(bytes, offsets.at("model")), 2.0f);
    EXPECT_EQ(readBlockAt<float>(bytes, offsets.at("model") + 48 + 4), 2.0f) << "column 3, row 1";
    EXPECT_EQ(readBlockAt<std::uint64_t>(bytes, offsets.at("vertices")), 0x1122334455667788ull);
    EXPECT_EQ(readBlockAt<std::uint32_t>(bytes, offsets.at("materialIndex")), 7u);
    EXPECT_EQ(readBlockAt<float>(bytes, offsets.at("exposure")), 1.5f);
    EXPECT_EQ(sizeof push, 80u);
}

TEST(BlockStructs, ScalarStorageBlockFixedPart) {
    const auto offsets =
        spirvMemberOffsets(layoutsStage("layouts", prism::catalog::Stage::Fragment).spirv, "Materials");
    EXPECT_EQ(offsetof(blocks::layouts::Materials, tint), offsets.at("tint")) << "scalar: right after roughness";
    EXPECT_EQ(sizeof(blocks::layouts::Materials), offsets.at("factors")) << "the fixed part ends at factors[]";
    blocks::layouts::Unused unused{};
    unused.read[2] = 4.0f;  // std140: 16 bytes an element
    const auto unusedOffsets =
        spirvMemberOffsets(layoutsStage("layouts", prism::catalog::Stage::Fragment).spirv, "Unused");
    EXPECT_EQ(readBlockAt<float>(reinterpret_cast<const std::byte*>(&unused), unusedOffsets.at("read") + 32), 4.0f);
}

}  // namespace
