// Part of stage 5 (validation_scheduler.hpp): the active attributes and uniforms of a
// linked program (glslang's reflection), with attribute locations taken from the binding
// contract.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

struct ProgramReflection {
    std::vector<ReflectedAttribute> attributes;  // sorted by location, then name
    std::vector<ReflectedUniform> uniforms;      // sorted by name
};

// `program` must be linked.
ProgramReflection reflectProgram(glslang::TProgram& program, const Contract& contract);

}  // namespace prism::shaderc
