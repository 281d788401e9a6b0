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
    int location = -1;  // from the contract; -1 when the contract does not place it
};

struct ReflectedUniform {
    std::string name;
    std::uint32_t glType = 0;
    int arraySize = 1;
};

struct ReflectedBlockMember {
    std::string name;
    std::uint32_t glType = 0;
    std::uint32_t offset = 0;  // bytes from the block's start
    int arraySize = 1;
};

struct ReflectedResource {
    std::string name;
    std::uint32_t set = 0, binding = 0;
    catalog::ResourceKind kind = catalog::ResourceKind::UniformBuffer;
    std::uint32_t size = 0;  // bytes of a buffer block; 0 otherwise
    std::uint32_t arraySize = 1;
    std::vector<ReflectedBlockMember> members = {};  // a uniform block's, by offset
};

struct ReflectedPushConstant {
    std::string name;
    std::uint32_t glType = 0, offset = 0, size = 0;
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
    std::vector<ReflectedSpecConstant> specConstants;  // by id
    std::vector<StageSpirv> spirv;                     // one per stage, in the program's stage order
};

// `program` must be linked.
ProgramReflection reflectProgram(glslang::TProgram& program, const Contract& contract);

}  // namespace prism::shaderc
