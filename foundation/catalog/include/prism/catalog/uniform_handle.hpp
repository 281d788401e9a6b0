// Typed uniform handles: what a generated catalogue header declares for each uniform of
// each shader, so that a misspelt uniform, a value of the wrong type or another shader's
// uniform is a compile error instead of a warning at run time (after sokol-shdc's
// generated uniform structs).
//
// For shader `toon` of the catalogue in namespace `lit`, the header prism-shaderc writes
// holds, for every uniform any variant of `toon` has (the union over its variants):
//
//     namespace lit::toon {
//     struct Shader { static constexpr ShaderId id = ShaderId::toon; };  // the tag
//     template <prism::catalog::GlslType T, std::size_t N>
//     using Uniform = prism::catalog::UniformHandle<T, N, Shader>;
//     inline constexpr Uniform<prism::catalog::GlslType::Float, 1> u_bands{"u_bands"};
//     }
//
// and in `<namespace>::contract` a handle for every uniform of the binding contract (tag
// `contract::Contract`), for runtime code that feeds whichever program it is given.
// A handle is a name with its GLSL type, its array length and its shader in the type;
// prism::gl::Program::set(handle, value) and prism::gl::ProgramOf<Tag> (prism/gl/program.hpp)
// check the value's C++ type and the shader against them at compile time. A plain Program
// only learns its shader at run time: shaderOf<Tag>() gives it the catalogue entry of a
// shader tag, so that set() refuses another shader's handle there.
//
// Usage (snippet: examples/snippets/catalog_uniform_handle.cpp):
//
//     #include "prism/catalog/uniform_handle.hpp"
//     struct Toon {};  // a generated header's tag
//     constexpr prism::catalog::UniformHandle<prism::catalog::GlslType::Vec3, 4, Toon> u_lights{"u_lights"};
//     static_assert(u_lights.arrayLength == 4 && u_lights.type == prism::catalog::GlslType::Vec3);
//     static_assert(prism::catalog::glslTypeName(u_lights.type) == "vec3");
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "prism/catalog/shader_catalog.hpp"

namespace prism::catalog {

// The GLSL type of a uniform. `Sampler` is every sampler type (set with a texture unit);
// `Other` is a type no setter writes (images, uvecN, bvecN, mat2, ...): its handle exists but
// cannot be set.
enum class GlslType : std::uint8_t {
    Float,
    Vec2,
    Vec3,
    Vec4,
    Int,
    IVec2,
    IVec3,
    IVec4,
    UInt,
    Bool,
    Mat3,
    Mat4,
    Sampler,
    Other
};

constexpr std::string_view glslTypeName(GlslType t) {
    switch (t) {
        case GlslType::Float: return "float";
        case GlslType::Vec2: return "vec2";
        case GlslType::Vec3: return "vec3";
        case GlslType::Vec4: return "vec4";
        case GlslType::Int: return "int";
        case GlslType::IVec2: return "ivec2";
        case GlslType::IVec3: return "ivec3";
        case GlslType::IVec4: return "ivec4";
        case GlslType::UInt: return "uint";
        case GlslType::Bool: return "bool";
        case GlslType::Mat3: return "mat3";
        case GlslType::Mat4: return "mat4";
        case GlslType::Sampler: return "sampler";
        case GlslType::Other: return "other";
    }
    return "?";
}

// One uniform of the shader tagged `ShaderTag`: `Length` is 1 for a non-array, else the
// longest array any variant declares.
template <GlslType Type, std::size_t Length, class ShaderTag>
struct UniformHandle {
    static constexpr GlslType type = Type;
    static constexpr std::size_t arrayLength = Length;
    using Shader = ShaderTag;
    std::string_view name;
};

// A generated header's shader tag: its `id` is that header's ShaderId, whose shaderInfo(ShaderId)
// (found by argument-dependent lookup, so any catalogue's header works) is the shader's
// catalogue entry. The contract's tag and hand-made tags are none: they name no shader.
template <class Tag>
concept CatalogShaderTag = requires {
    { shaderInfo(Tag::id) } -> std::same_as<const Shader&>;
};

// The catalogue entry of the shader tagged `Tag`: an index into the catalogue's shaders.
template <CatalogShaderTag Tag>
const Shader& shaderOf() {
    return shaderInfo(Tag::id);
}

}  // namespace prism::catalog
