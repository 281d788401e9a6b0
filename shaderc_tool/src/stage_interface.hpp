// The global interface of one compiled stage (its ins, outs and uniforms), extracted
// from glslang's AST into plain structs so the interface and contract checks are
// testable without glslang.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

namespace glslang {
class TShader;
}

namespace prism::shaderc {

// Ray-tracing data (Vulkan GLSL): rayPayloadEXT / rayPayloadInEXT, hitAttributeEXT,
// callableDataEXT / callableDataInEXT.
enum class StorageKind {
    In,
    Out,
    Uniform,
    Buffer,
    RayPayload,
    RayPayloadIn,
    HitAttribute,
    CallableData,
    CallableDataIn
};
enum class Interpolation { Smooth, Flat, NoPerspective };

struct InterfaceVariable {
    std::string name;  // block name for interface blocks
    StorageKind storage = StorageKind::In;
    std::string type;   // GLSL spelling without array: "vec3", "mat4", "sampler2D", struct name
    int arraySize = 0;  // 0 = not an array, -1 = unsized, else the (outer) size
    Interpolation interpolation = Interpolation::Smooth;
    bool isBlock = false;
    bool patch = false;         // `patch in` / `patch out`: per patch, not an array over its vertices
    int location = -1;          // layout(location = N): explicit, or glslang's after mapIO; -1 without
    int locationSlots = 1;      // locations it takes (one vertex's, for a per-vertex array)
    bool perPrimitive = false;  // perprimitiveEXT: a mesh stage's per-primitive output, its fragment input
    int set = 0;                // a uniform's or buffer's descriptor set (0 unless declared)
    int binding = -1;           // layout(binding = N); -1 without
    bool pushConstant = false;  // layout(push_constant): no descriptor
    std::string structure;      // a struct's members, recursively ("float a; vec3 b[2];"); "" otherwise
    std::string memberTypes;    // the same without names ("float; vec3[2];"): a block's type where it meets another
    std::uint32_t sourceNumber = 0;  // from the #line directives
    int line = 0;
    int column = 0;
};

struct StageInterface {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::vector<InterfaceVariable> variables;  // user-declared globals only (no gl_*)
};

// Walks the linker objects of a successfully parsed shader.
StageInterface extractStageInterface(catalog::Stage stage, const glslang::TShader& shader);

std::string glslTypeWithArray(const InterfaceVariable& v);
std::string_view interpolationName(Interpolation i);

}  // namespace prism::shaderc
