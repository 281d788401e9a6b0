// Comment- and layout-blind signatures of GLSL files (see code_signature.hpp).
#include "code_signature.hpp"

#include <filesystem>

#include "stage_files.hpp"

namespace prism::shaderc {

std::string codeSignature(std::string_view text) {
    if (text.find("__LINE__") != std::string_view::npos) return std::string(text);
    std::string out, line;
    bool inBlockComment = false;
    const auto endLine = [&] {
        while (!line.empty() && line.back() == ' ') line.pop_back();
        if (!line.empty()) out += line + "\n";
        line.clear();
    };
    const auto addBlank = [&] {
        if (!line.empty() && line.back() != ' ') line += ' ';
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (inBlockComment) {
            if (c == '*' && next == '/') {  // the whole comment, newlines included, is one blank, as
                inBlockComment = false;     // for the preprocessor: a directive goes on after it
                ++i;
                addBlank();
            }
            continue;
        }
        if (c == '/' && next == '*') {
            inBlockComment = true;
            ++i;
            continue;
        }
        if (c == '/' && next == '/') {  // to the end of the line; a trailing backslash keeps the next line
            while (i < text.size() && text[i] != '\n') ++i;
            endLine();
            continue;
        }
        if (c == '"') {  // #include "..." and the like: kept as written
            const std::size_t close = text.find_first_of("\"\n", i + 1);
            const std::size_t end = close == std::string_view::npos ? text.size() : close;
            line.append(text.substr(i, end - i + (end < text.size() && text[end] == '"' ? 1 : 0)));
            i = end < text.size() && text[end] == '"' ? end : end - 1;
            continue;
        }
        if (c == '\n') {
            endLine();
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            addBlank();
        } else {
            line += c;
        }
    }
    endLine();
    return out;
}

bool hasCodeSignature(std::string_view path) {
    return path.ends_with(kModuleExtension) || stageOfPath(std::filesystem::path(path)).has_value();
}

}  // namespace prism::shaderc
