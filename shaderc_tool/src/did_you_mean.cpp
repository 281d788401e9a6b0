// "Did you mean" hints of the tool: the function names of a stage
// (see did_you_mean.hpp; the edit-distance rule is prism/catalog/did_you_mean.hpp).
#include "did_you_mean.hpp"

#include <algorithm>
#include <regex>
#include <set>

namespace prism::shaderc {

namespace {

// The text with comments replaced by spaces (line breaks kept).
std::string withoutComments(std::string_view text) {
    std::string out(text);
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            out[i] = out[i + 1] = ' ';
            for (i += 2; i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/'); ++i)
                if (out[i] != '\n') out[i] = ' ';
            if (i + 1 < out.size()) out[i] = out[i + 1] = ' ';
        }
    }
    return out;
}

}  // namespace

std::vector<std::string> functionNamesIn(std::string_view glsl) {
    static const std::regex function(
        R"(^[ \t]*(?:(?:highp|mediump|lowp|precise|invariant)[ \t]+)*)"       // qualifiers
        R"([A-Za-z_]\w*(?:[ \t]*\[[^\]]*\])?[ \t]+([A-Za-z_]\w*)[ \t]*\()");  // type, name, '('

    static const std::set<std::string> notTypes = {"return", "else", "if", "while", "for", "switch", "case", "do"};
    std::set<std::string> names;
    const std::string text = withoutComments(glsl);
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        std::smatch m;
        if (std::regex_search(line, m, function)) {
            const std::string first = line.substr(line.find_first_not_of(" \t"));
            const std::string typeWord = first.substr(0, first.find_first_of(" \t["));
            if (!notTypes.contains(typeWord)) names.insert(m[1]);
        }
        start = end + 1;
    }
    return {names.begin(), names.end()};
}

}  // namespace prism::shaderc
