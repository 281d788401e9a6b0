// Part of stage 3 (shader_inputs.hpp). The binding contract: the vertex attributes and
// uniforms the runtime supplies, declared once in a JSON file (modules/contract.json). A
// shader that declares an attribute or uniform outside it is an error, because a misspelled
// name would otherwise silently receive no data (the failure the FUDGE shader thesis §3
// describes: mistakes in shader strings show up only at run time).
//
//   { "attributes": [ { "name": "a_position", "type": "vec3", "location": 0 } ],
//     "uniforms":   [ { "name": "u_world", "type": "mat4" },
//                     { "name": "u_lightDirection", "type": "vec3", "array": 8 } ] }
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "interface_check.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct ContractAttribute {
    std::string name, type;
    int location = 0;
};

struct ContractUniform {
    std::string name, type;
    int array = 0;  // 0 = not an array; else the largest size a shader may declare
};

struct Contract {
    std::vector<std::string> files;             // where it was read from
    std::vector<ContractAttribute> attributes;  // sorted by location
    std::vector<ContractUniform> uniforms;      // sorted by name
    bool empty() const { return files.empty(); }
};

struct ContractLoadResult {
    Contract contract;
    std::vector<Diagnostic> diagnostics;
    bool ioError = false;  // a contract file that cannot be read
};

// Reads and merges the contract files; a malformed file gives `file:line:col` and the
// JSON path of the offending value.
ContractLoadResult loadContracts(const std::vector<std::string>& paths, const SourceReader& reader);

// Checks the vertex stage's inputs and every stage's plain uniforms (not blocks).
std::vector<Diagnostic> checkContract(const Contract& contract, const std::vector<StageInterface>& stages,
                                      const SourceLocator& locate);

// GL enum of a GLSL type name (GL_FLOAT_VEC3 ...), 0 when unknown.
std::uint32_t glTypeOf(const std::string& glslType);

}  // namespace prism::shaderc
