// What the differential corpus checks on Prism's outputs: spirv-val's layout options read from a SPIR-V
// module's OpSourceExtension lines, and the GLSL ES 3.00 rule that nothing is left at lowp.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
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

// The lines of glslang's intermediate tree (`glslangValidator -i`) of GLSL ES stages that
// compute or declare something at lowp. GLSL ES 3.00 gives sampler2D and samplerCube a default
// of lowp in every stage (§4.5.4), which SwiftShader runs at 32 bits, so only the text shows
// it; glslang's tree applies every precision rule (statements, qualifiers, struct members).
inline std::string lowpLines(const std::string& tree) {
    std::istringstream in(tree);
    std::string line, found;
    while (std::getline(in, line))
        if (line.find(" lowp ") != std::string::npos) found += line + "\n";
    return found;
}

}  // namespace prism::test
