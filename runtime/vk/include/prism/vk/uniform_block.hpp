// The bytes of one std140 uniform block, written by member NAME at the offsets the
// catalogue's reflection gives (catalog::Resource::members): how a Vulkan draw feeds the
// loose uniforms that the spirv target packs into `gl_DefaultUniformBlock`. It answers the
// same calls as prism::gl::Program's setters, so the frame uniforms of prism_render fill
// either (prism/render/frame_uniforms.hpp).
//
// Usage (snippet: examples/snippets/vk_uniform_block.cpp):
//
//     #include "prism/vk/uniform_block.hpp"
//     #include "prism/shaders.hpp"  // generated catalogue, built with TARGETS gl spirv
//     const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
//     const prism::catalog::Resource& block = phong.variants[0].resources[0];  // gl_DefaultUniformBlock
//     prism::vk::UniformBlock uniforms(block, "phong");
//     uniforms.set("u_shininess", 32.0f);                             // at u_shininess's offset
//     uniforms.set(prism::shaders::contract::u_color, glm::vec4(1));  // typed handle
//     std::span<const std::byte> bytes = uniforms.bytes();            // block.size bytes
//
// std140 as the reflection states it: each member at its offset; array elements and
// matrix columns 16 bytes apart. A name the block lacks, or a value whose type differs
// from the member's, throws std::invalid_argument naming both; a typed handle of a uniform
// this variant compiled out is a no-op, as in prism::gl::Program.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/catalog/uniform_handle.hpp"

namespace prism::vk {

class UniformBlock {
  public:
    // `offsetFault` shifts every member's offset by that many bytes: a fault the agreement
    // tests inject to show they catch a member at a wrong offset. Leave it 0.
    UniformBlock(const catalog::Resource& block, std::string label, int offsetFault = 0);

    const std::string& label() const { return label_; }
    std::span<const std::byte> bytes() const { return bytes_; }
    // True for a member's name, and for `a[i]` of an array member `a` of more than i elements.
    bool hasUniform(std::string_view name) const;

    void set(std::string_view name, float value);
    void set(std::string_view name, int value);
    void set(std::string_view name, unsigned value);
    void set(std::string_view name, bool value);
    void set(std::string_view name, const glm::vec2& value);
    void set(std::string_view name, const glm::vec3& value);
    void set(std::string_view name, const glm::vec4& value);
    void set(std::string_view name, const glm::mat3& value);
    void set(std::string_view name, const glm::mat4& value);
    void set(std::string_view name, std::span<const float> values);
    void set(std::string_view name, std::span<const glm::vec3> values);
    void set(std::string_view name, std::span<const glm::vec4> values);

    // Typed set (prism/catalog/uniform_handle.hpp): a no-op for a uniform the block lacks.
    template <catalog::GlslType T, std::size_t N, class Tag, class V>
    void set(const catalog::UniformHandle<T, N, Tag>& uniform, const V& value) {
        if (!hasUniform(uniform.name)) return;
        if constexpr (N == 1)
            set(uniform.name, value);
        else
            set(uniform.name, std::span<const typename V::value_type>(value));
    }

  private:
    struct Slot {
        std::size_t offset;
        std::uint32_t glType;
        std::int32_t elements;  // array elements from this one on
    };
    // The member's slot for `name` ("a" or "a[i]"), its type checked against `glType`.
    Slot slot(std::string_view name, std::uint32_t glType) const;
    void write(std::string_view name, std::uint32_t glType, const float* values, int count, int columns, int rows);

    const catalog::Resource* block_;
    std::string label_;
    int offsetFault_;
    std::vector<std::byte> bytes_;
};

}  // namespace prism::vk
