// Part of stage 5 (validation_scheduler.hpp): the active attributes and uniforms of a
// linked program (glslang's reflection), with attribute locations taken from the binding
// contract. The descriptors, push constants, specialisation constants and SPIR-V of a program
// compiled to SPIR-V (the Vulkan client, the spirv target) are filled in by vulkan_reflection.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "contract.hpp"

namespace glslang {
class TProgram;
}

namespace prism::shaderc {

struct ReflectedAttribute {
    std::string name;
    std::uint32_t glType = 0;
    int location = -1;          // from the contract; -1 when the contract does not place it
    bool used = true;           // SPIR-V: statically read by the vertex stage (OpenGL lists only those)
    std::string glslType = {};  // SPIR-V: the type's GLSL name ("f16vec2": not every type has a GL enum)
};

struct ReflectedUniform {
    std::string name;
    std::uint32_t glType = 0;
    int arraySize = 1;
};

// A leaf of a block (nested structs flattened to `a.b`, arrays of structs to `a[i].b`).
struct ReflectedBlockMember {
    std::string name;
    std::uint32_t glType = 0;
    std::uint32_t offset = 0;  // bytes from the block's start
    int arraySize = 1;         // catalog::kUnboundedArray for a runtime array
    std::uint32_t size = 0;    // bytes of the whole member (0: a runtime array), SPIR-V only
    std::uint32_t arrayStride = 0;
    bool deviceAddress = false;  // a buffer_reference pointer: an 8-byte device address
    std::string glslType = {};   // SPIR-V: the type's GLSL name ("f16vec2": not every type has a GL enum)
};

// A struct type as the SPIR-V lays it out: what a generated C++ struct mirrors.
struct ReflectedStructMember {
    std::string name;
    std::string glslType;                       // "vec3", "uint64_t"; a nested struct's own name
    std::uint32_t offset = 0, size = 0;         // size: the whole member, every element (0: runtime array)
    std::vector<std::uint32_t> arrayDims = {};  // outermost first; catalog::kUnboundedArray for []
    std::uint32_t arrayStride = 0, matrixStride = 0;
    bool rowMajor = false, deviceAddress = false;
    int structIndex = -1;  // a nested struct: its index in the owning ReflectedBlockLayout
};
struct ReflectedStruct {
    std::string name;
    std::uint32_t size = 0;  // the declared size (a runtime array counts 0 elements)
    std::vector<ReflectedStructMember> members;
};
// structs[0] is the block; nested struct types follow.
using ReflectedBlockLayout = std::vector<ReflectedStruct>;

struct ReflectedResource {
    std::string name;
    std::uint32_t set = 0, binding = 0;
    catalog::ResourceKind kind = catalog::ResourceKind::UniformBuffer;
    std::uint32_t size = 0;                          // bytes of a buffer block (its fixed part); 0 otherwise
    std::uint32_t arraySize = 1;                     // catalog::kUnboundedArray for `name[]`
    std::vector<ReflectedBlockMember> members = {};  // a buffer block's leaves, by offset
    std::uint32_t runtimeStride = 0;                 // a storage block ending in `T x[]`: the bytes of one T
    bool used = true;                                // statically used by some stage
    ReflectedBlockLayout layout = {};                // a buffer block's type (SPIR-V only)
};

struct ReflectedPushConstant {
    std::string name;
    std::uint32_t glType = 0, offset = 0, size = 0;
    int arraySize = 1;
    std::uint32_t arrayStride = 0;
    bool deviceAddress = false;  // a buffer_reference pointer: 8 bytes, glType GL_UNSIGNED_INT64_ARB
    std::string glslType = {};
};

struct ReflectedSpecConstant {
    std::string name;
    std::uint32_t id = 0, glType = 0, defaultBits = 0;
};

struct StageSpirv {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::vector<std::uint32_t> words;
};

struct ProgramReflection {
    std::vector<ReflectedAttribute> attributes;  // sorted by location, then name
    std::vector<ReflectedUniform> uniforms;      // sorted by name
    // The SPIR-V's (the Vulkan client, the spirv target; empty for OpenGL GLSL):
    std::vector<ReflectedResource> resources;          // by set, then binding
    std::vector<ReflectedPushConstant> pushConstants;  // by offset
    ReflectedBlockLayout pushConstantLayout;           // the push-constant block's type; empty without one
    std::vector<ReflectedSpecConstant> specConstants;  // by id
    std::vector<StageSpirv> spirv;                     // one per stage, in the program's stage order
};

// `program` must be linked.
ProgramReflection reflectProgram(glslang::TProgram& program, const Contract& contract);

}  // namespace prism::shaderc
