// The lexical fixpoint behind variant sharing (see structural_macros.hpp).
#include "structural_macros.hpp"

#include <cctype>

#include "directive_lines.hpp"

namespace prism::shaderc {
namespace {

std::vector<std::string> identifiersIn(std::string_view text) {
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '"') {  // a quoted name is not expanded
            const auto close = text.find('"', i + 1);
            i = close == std::string_view::npos ? text.size() : close + 1;
        } else if (std::isalpha(c) || c == '_') {
            std::size_t j = i + 1;
            while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_')) ++j;
            ids.emplace_back(text.substr(i, j - i));
            i = j;
        } else if (std::isdigit(c)) {  // a number's suffix (1u, 0x1F) is not an identifier
            while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
        } else {
            ++i;
        }
    }
    return ids;
}

constexpr std::size_t kNoGroup = static_cast<std::size_t>(-1);

// A conditional group: the identifiers of all its branches' conditions, and the group
// around it. Directives refer to their innermost group, so nothing is copied per line.
struct Group {
    std::vector<std::string> conditions;
    std::size_t parent = kNoGroup;
    bool counted = false;  // its conditions (and its parents') are structural already
};

// One directive that matters to the fixpoint.
struct DirectiveFacts {
    bool decisive = false;
    std::string defines;           // the macro a #define / #undef names, else ""
    std::vector<std::string> own;  // identifiers of the line that glslang may expand
    std::size_t group = kNoGroup;  // the innermost group around it
    bool counted = false;          // its words are in the set
};

}  // namespace

std::optional<StructuralMacros> structuralMacros(const std::vector<std::string_view>& texts) {
    StructuralMacros result;
    std::vector<Group> groups;
    std::vector<DirectiveFacts> facts;
    for (const auto text : texts) {
        if (text.find("##") != std::string_view::npos) return std::nullopt;
        std::size_t open = kNoGroup;  // innermost open group of this file
        for (const auto& line : splitLogicalLines(text)) {
            const auto directive = parseDirective(line);
            if (!directive || directive->name.empty()) continue;
            const std::string& name = directive->name;
            auto ids = identifiersIn(directive->argument);
            if (name == "if" || name == "ifdef" || name == "ifndef") {
                groups.push_back({std::move(ids), open, false});
                open = groups.size() - 1;
            } else if (name == "elif" || name == "else") {
                if (open == kNoGroup) return std::nullopt;
                auto& conditions = groups[open].conditions;
                conditions.insert(conditions.end(), ids.begin(), ids.end());
            } else if (name == "endif") {
                if (open == kNoGroup) return std::nullopt;
                open = groups[open].parent;
            } else {
                DirectiveFacts f;
                f.group = open;
                if (name == "define" || name == "undef") {
                    if (ids.empty()) continue;  // malformed: glslang reports it
                    f.defines = ids.front();
                    if (name == "define") result.defined.insert(ids.front());
                    f.own = std::move(ids);
                } else {
                    f.decisive = true;
                    const bool headerName = name == "include" && directive->argument.starts_with('<');
                    if (!expandsNoMacros(*directive) && !headerName) f.own = std::move(ids);
                }
                facts.push_back(std::move(f));
            }
        }
        if (open != kNoGroup) return std::nullopt;
    }
    for (bool grew = true; grew;) {
        grew = false;
        for (auto& f : facts) {
            if (f.counted || (!f.decisive && !result.decisive.contains(f.defines))) continue;
            f.counted = true;
            for (const auto& id : f.own) grew = result.decisive.insert(id).second || grew;
            for (std::size_t g = f.group; g != kNoGroup && !groups[g].counted; g = groups[g].parent) {
                groups[g].counted = true;
                for (const auto& id : groups[g].conditions) grew = result.decisive.insert(id).second || grew;
            }
        }
    }
    return result;
}

}  // namespace prism::shaderc
