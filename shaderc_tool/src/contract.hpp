// Part of stage 3 (shader_inputs.hpp). The binding contract: the vertex attributes and
// uniforms the runtime supplies, declared once in a JSON file (modules/contract.json). A
// shader's attribute or uniform within edit distance 2 of a contract name, but not equal to it, is a misspelling that
// would silently receive no data (the failure the FUDGE shader thesis §3 describes:
// mistakes in shader strings show up only at run time), so it is an error with "did you
// mean". Names far from every contract name are the shader's own (lygia's `u_time`,
// `u_resolution`) and pass. Without --contract the tool still knows Prism's own contract,
// compiled in: then a near miss is a warning, since the names may be the user's.
//
//   { "attributes": [ { "name": "a_position", "type": "vec3", "location": 0 } ],
//     "uniforms":   [ { "name": "u_world", "type": "mat4" },
//                     { "name": "u_lightDirection", "type": "vec3", "array": 8 } ] }
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "diagnostics.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

struct ContractAttribute {
    std::string name, type;
    int location = 0;
    std::string entry;  // where it is declared, for messages: "contract.json /attributes/0"
};

struct ContractUniform {
    std::string name, type;
    int array = 0;  // 0 = not an array; else the largest size a shader may declare
};

struct Contract {
    std::vector<std::string> files;             // where it was read from (none for the built-in one)
    std::vector<ContractAttribute> attributes;  // sorted by location
    std::vector<ContractUniform> uniforms;      // sorted by name
    bool builtIn = false;                       // Prism's own, taken for want of --contract
    bool empty() const { return files.empty() && !builtIn; }
};

struct ContractLoadResult {
    Contract contract;
    std::vector<Diagnostic> diagnostics;
    bool ioError = false;  // a contract file that cannot be read
};

// Reads and merges the contract files; a malformed file gives `file:line:col` and the
// JSON path of the offending value. No paths: Prism's built-in contract.
ContractLoadResult loadContracts(const std::vector<std::string>& paths, const SourceReader& reader);

// The text of Prism's modules/contract.json, compiled into the tool
// (shaderc_tool/CMakeLists.txt writes it from builtin_contract.cpp.in).
std::string_view builtInContractJson();

// GL enum of a GLSL type name (GL_FLOAT_VEC3 ...), 0 when unknown.
std::uint32_t glTypeOf(const std::string& glslType);

// The GLSL type name of a GL enum ("vec3" for GL_FLOAT_VEC3), "" when unknown; glTypeOf's inverse.
std::string glslTypeNameOf(std::uint32_t glType);

}  // namespace prism::shaderc
