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

bool isConditional(const std::string& name) {
    return name == "if" || name == "ifdef" || name == "ifndef" || name == "elif" || name == "else" || name == "endif";
}

// Directives whose words glslang takes as they are written, never macro-expanded: only
// whether the line is reached can differ between runs.
bool unexpanded(const std::string& name) {
    return name == "pragma" || name == "extension" || name == "version" || name == "error";
}

// One directive that matters to the fixpoint.
struct DirectiveFacts {
    bool decisive = false;
    std::string defines;                 // the macro a #define / #undef names, else ""
    std::vector<std::string> own;        // identifiers of the line itself
    std::vector<std::string> enclosing;  // identifiers of the conditions of the groups around it
};

}  // namespace

std::optional<StructuralMacros> structuralMacros(const std::vector<std::string_view>& texts) {
    StructuralMacros result;
    std::vector<DirectiveFacts> facts;
    for (const auto text : texts) {
        if (text.find("##") != std::string_view::npos) return std::nullopt;
        std::vector<std::vector<std::string>> groups;  // condition identifiers of each open group
        for (const auto& line : splitLogicalLines(text)) {
            const auto directive = parseDirective(line);
            if (!directive || directive->name.empty()) continue;
            const std::string& name = directive->name;
            auto ids = identifiersIn(directive->argument);
            if (name == "if" || name == "ifdef" || name == "ifndef") {
                groups.push_back(std::move(ids));
                continue;
            }
            if (name == "elif" || name == "else") {
                if (groups.empty()) return std::nullopt;
                groups.back().insert(groups.back().end(), ids.begin(), ids.end());
                continue;
            }
            if (name == "endif") {
                if (groups.empty()) return std::nullopt;
                groups.pop_back();
                continue;
            }
            DirectiveFacts f;
            if ((name == "define" || name == "undef") && !ids.empty()) {
                f.defines = ids.front();
                if (name == "define") result.defined.insert(ids.front());
                f.own = std::move(ids);
            } else {
                f.decisive = !isConditional(name);
                const bool headerName = name == "include" && directive->argument.starts_with('<');
                if (!unexpanded(name) && !headerName) f.own = std::move(ids);
            }
            for (const auto& g : groups) f.enclosing.insert(f.enclosing.end(), g.begin(), g.end());
            facts.push_back(std::move(f));
        }
        if (!groups.empty()) return std::nullopt;
    }
    for (bool grew = true; grew;) {
        grew = false;
        for (const auto& f : facts) {
            if (!f.decisive && !result.decisive.contains(f.defines)) continue;
            for (const auto* list : {&f.own, &f.enclosing})
                for (const auto& id : *list) grew = result.decisive.insert(id).second || grew;
        }
    }
    return result;
}

}  // namespace prism::shaderc
