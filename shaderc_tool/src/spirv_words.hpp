// Reading a SPIR-V module's words (SPIR-V specification, section 2.3): each instruction in
// order, and a literal string operand. Shared by the validator's message locator
// (spirv_codegen.cpp) and the reflection's constants (vulkan_reflection.cpp).
//
//     forEachInstruction(words, [&](std::uint32_t op, std::span<const std::uint32_t> operands, std::size_t) {
//         if (op == 5) names[operands[0]] = literalString(operands.subspan(1));  // OpName
//         return true;                                                          // go on
//     });
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace prism::shaderc {

// Calls `visit(opcode, operands, index)` for each instruction (index from 1, as SPIRV-Tools
// counts them in its messages' position) until it returns false or the words end; a word
// count that runs past the end stops it.
template <class Visit>
void forEachInstruction(std::span<const std::uint32_t> words, Visit visit) {
    constexpr std::size_t kHeaderWords = 5;
    std::size_t index = 0;
    for (std::size_t at = kHeaderWords; at < words.size();) {
        const std::uint32_t count = words[at] >> 16;
        if (count == 0 || at + count > words.size()) return;
        if (!visit(words[at] & 0xFFFF, words.subspan(at + 1, count - 1), ++index)) return;
        at += count;
    }
}

// A literal string operand: UTF-8 bytes, four a word, up to the first NUL.
inline std::string literalString(std::span<const std::uint32_t> operands) {
    std::string s;
    for (auto word : operands)
        for (int byte = 0; byte < 4; ++byte) {
            const char c = static_cast<char>((word >> (8 * byte)) & 0xFF);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

}  // namespace prism::shaderc
