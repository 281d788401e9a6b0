// Validation keys of flattened stages (see validation_key.hpp).
#include "validation_key.hpp"

#include <algorithm>
#include <cctype>

#include "code_signature.hpp"
#include "prism/hash/content_hash.hpp"
#include "directive_lines.hpp"

namespace prism::shaderc {
namespace {

// `#line N` or `#line N S` with plain numbers, as the flattener writes them; any other
// #line (a malformed one is an error) stays in the key.
bool isLineMarker(std::string_view line) {
    if (!line.starts_with("#line ")) return false;
    int numbers = 0;
    for (std::size_t i = 6; i < line.size();) {
        if (!std::isdigit(static_cast<unsigned char>(line[i]))) return false;
        while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
        ++numbers;
        if (i < line.size() && line[i++] != ' ') return false;
    }
    return numbers == 1 || numbers == 2;
}

std::string bodyHash(std::string_view text, std::size_t defineCount) {
    std::size_t bodyStart = 0;  // below the #version line and the define block
    for (std::size_t line = 0; line < 1 + defineCount && bodyStart < text.size(); ++line) {
        const auto end = text.find('\n', bodyStart);
        bodyStart = end == std::string_view::npos ? text.size() : end + 1;
    }
    const std::string_view body = text.substr(bodyStart);
    hash::ContentHash key;
    if (body.find("__LINE__") != std::string_view::npos || body.find("__FILE__") != std::string_view::npos) {
        key.add("whole").add(body);
        return key.hex();
    }
    const std::string signature = codeSignature(body);
    for (std::size_t start = 0; start < signature.size();) {
        std::size_t end = signature.find('\n', start);
        if (end == std::string::npos) end = signature.size();
        const std::string_view line = std::string_view(signature).substr(start, end - start);
        if (!isLineMarker(line)) key.add(line);
        start = end + 1;
    }
    return key.hex();
}

std::vector<std::string> namesOf(const DefineList& defines) {
    std::vector<std::string> names;
    for (const auto& d : defines) names.push_back(d.first);
    return names;
}

}  // namespace

ValidationKeyBasis validationKeyBasis(const ResolvedStage& stage, std::size_t defineCount,
                                      const std::vector<std::string>& names, const SourceReader& reader) {
    ValidationKeyBasis basis;
    basis.body = bodyHash(stage.text, defineCount);
    std::vector<std::string> texts;  // each file's code where glslang expands macros
    bool everyName = false;          // a file pastes tokens, or cannot be read
    for (const auto& path : stage.filesRead) {
        const auto text = reader.read(path);
        everyName = everyName || !text || text->find("##") != std::string::npos;
        if (!text) continue;
        std::string code;
        for (const auto& line : splitLogicalLines(*text)) {
            const auto directive = parseDirective(line);
            if (directive && expandsNoMacros(*directive)) continue;
            code += line.code;
            code += '\n';
        }
        texts.push_back(std::move(code));
    }
    for (const auto& name : names) {
        bool met = everyName;
        for (std::size_t t = 0; !met && t < texts.size(); ++t) met = findWord(texts[t], name) != std::string_view::npos;
        if (met) basis.met.push_back(name);
    }
    return basis;
}

std::string validationKey(const ResolvedStage& stage, const DefineList& defines, const ValidationKeyBasis& basis) {
    hash::ContentHash key;
    key.add("validation key 1").add(stage.versionDirective).add(basis.body);
    const auto met = [&](const std::string& name) {
        if (std::find(basis.met.begin(), basis.met.end(), name) != basis.met.end()) return true;
        for (const auto& [other, value] : defines)  // a macro's value can name it
            if (findWord(value, name) != std::string_view::npos) return true;
        return false;
    };
    for (const auto& [name, value] : defines)
        if (met(name)) key.add(name).add(value);
    return key.hex();
}

std::string validationKey(const ResolvedStage& stage, const DefineList& defines, const SourceReader& reader) {
    return validationKey(stage, defines, validationKeyBasis(stage, defines.size(), namesOf(defines), reader));
}

}  // namespace prism::shaderc
