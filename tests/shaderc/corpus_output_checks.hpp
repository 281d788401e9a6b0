// What the differential corpus checks on Prism's outputs: spirv-val's layout options read from a SPIR-V
// module's OpSourceExtension lines, and the GLSL ES 3.00 rule that no sampler is left at its lowp default.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace prism::test {

// The extensions a SPIR-V module says its source enabled (OpSourceExtension, opcode 4; glslang writes one
// per `#extension` line). Empty for a file that is not SPIR-V.
inline std::set<std::string> spirvSourceExtensions(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<std::uint32_t> words;
    for (std::uint32_t w; in.read(reinterpret_cast<char*>(&w), sizeof w);) words.push_back(w);
    std::set<std::string> extensions;
    if (words.size() < 5 || words[0] != 0x07230203u) return extensions;
    for (std::size_t at = 5; at < words.size();) {
        const std::uint32_t count = words[at] >> 16, opcode = words[at] & 0xffffu;
        if (count == 0 || at + count > words.size()) break;
        if (opcode == 4) {
            const char* chars = reinterpret_cast<const char*>(&words[at + 1]);
            extensions.insert(std::string(chars, strnlen(chars, (count - 1) * sizeof(std::uint32_t))));
        }
        at += count;
    }
    return extensions;
}

// The spirv-val options a careful user passes for a module whose source enabled these layout extensions.
inline std::vector<std::string> spirvValLayoutOptions(const std::set<std::string>& extensions) {
    std::vector<std::string> options;
    if (extensions.count("GL_EXT_scalar_block_layout")) options.push_back("--scalar-block-layout");
    if (extensions.count("GL_EXT_uniform_buffer_standard_layout"))
        options.push_back("--uniform-buffer-standard-layout");
    return options;
}

// Samplers of a GLSL ES 3.00 text that stay at lowp: sampler2D and samplerCube are the types GLSL ES 3.00
// predeclares `precision lowp` in both the vertex and the fragment language (section 4.5.3), so each
// declaration (a uniform, or a member of a uniform struct) needs a precision statement for its type before
// it or a precision qualifier of its own (a module that writes a precision asks for it). Returns
// "name (type)" for each one left at lowp.
inline std::vector<std::string> samplersLeftAtLowp(const std::string& esText) {
    static const std::regex declaration(
        R"((\b(?:lowp|mediump|highp)\s+)?\b(sampler2D|samplerCube)\s+(\w+)\s*(\[[^\]]*\])?\s*;)");
    std::vector<std::string> left;
    for (std::sregex_iterator it(esText.begin(), esText.end(), declaration), end; it != end; ++it) {
        const auto& m = *it;
        if (m[1].matched) continue;
        const std::regex statement("\\bprecision\\s+(lowp|mediump|highp)\\s+" + m[2].str() + "\\s*;");
        const std::string head = esText.substr(0, static_cast<std::size_t>(m.position(0)));
        if (!std::regex_search(head, statement)) left.push_back(m[3].str() + " (" + m[2].str() + ")");
    }
    return left;
}

}  // namespace prism::test
