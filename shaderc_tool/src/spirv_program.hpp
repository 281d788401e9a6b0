// The spirv target's result for one program, as the in-memory catalogue keeps it
// (catalog_model.hpp) and the data writer prints it: each stage's SPIR-V words and the
// program's reflection (spirv_target.hpp makes it).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

namespace prism::shaderc {

struct SpirvBlockMember {
    std::string name;
    std::uint32_t glType = 0;
    std::uint32_t offset = 0;  // bytes from the block's start (std140)
    int arraySize = 1;
};

struct SpirvBlock {
    std::string name;  // gl_DefaultUniformBlock for the packed loose uniforms
    std::uint32_t set = 0, binding = 0, size = 0;
    std::vector<SpirvBlockMember> members;  // by offset
};

struct SpirvSampler {
    std::string name;
    std::uint32_t glType = 0;
    std::uint32_t set = 0, binding = 0;
    int arraySize = 1;
};

struct SpirvInput {
    std::string name;
    std::uint32_t glType = 0;
    int location = 0;
};

struct SpirvReflection {
    std::vector<SpirvBlock> blocks;      // by set, binding
    std::vector<SpirvSampler> samplers;  // by set, binding
    std::vector<SpirvInput> inputs;      // by location
};

struct SpirvStage {
    catalog::Stage stage;
    std::vector<std::uint32_t> words;
};

struct SpirvProgram {
    std::vector<SpirvStage> stages;  // in the program's stage order
    SpirvReflection reflection;
};

}  // namespace prism::shaderc
