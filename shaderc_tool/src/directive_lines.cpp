// Logical lines, directive recognition and #version parsing (see directive_lines.hpp).
#include "directive_lines.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <set>

namespace prism::shaderc {
namespace {

// ---- lines and comments ----------------------------------------------------------

std::vector<std::string> splitPhysicalLines(std::string_view text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.emplace_back(line);
        start = end + 1;
    }
    return lines;
}

bool endsWithContinuation(const std::string& line) {
    return !line.empty() && line.back() == '\\';
}

bool startsWith(std::string_view text, std::size_t at, std::string_view prefix) {
    return text.substr(at, prefix.size()) == prefix;
}

// Replaces comments in `spliced` by spaces (same length). `inBlockComment` carries a
// /* */ comment over from the previous logical line and out to the next one. On a
// directive line a "..." string is opaque, so `#include "a//b"` keeps its name.
std::string blankComments(std::string_view spliced, bool& inBlockComment) {
    std::string code(spliced);
    bool inString = false;
    bool sawCode = false;
    bool directiveLine = false;
    std::size_t i = 0;
    while (i < code.size()) {
        if (inBlockComment) {
            if (startsWith(code, i, "*/")) {
                code[i] = code[i + 1] = ' ';
                inBlockComment = false;
                i += 2;
            } else {
                code[i++] = ' ';
            }
        } else if (inString) {
            inString = code[i++] != '"';
        } else if (startsWith(code, i, "//")) {
            std::fill(code.begin() + static_cast<std::ptrdiff_t>(i), code.end(), ' ');
            break;
        } else if (startsWith(code, i, "/*")) {
            code[i] = code[i + 1] = ' ';
            inBlockComment = true;
            i += 2;
        } else {
            const char c = code[i++];
            if (!sawCode && !std::isspace(static_cast<unsigned char>(c))) {
                sawCode = true;
                directiveLine = c == '#';
            }
            inString = directiveLine && c == '"';
        }
    }
    return code;
}

bool isIdentifierStart(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}

bool isIdentifierChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

// ---- public helpers ------------------------------------------------------------------

std::vector<LogicalLine> splitLogicalLines(std::string_view text) {
    const std::vector<std::string> physical = splitPhysicalLines(text);
    std::vector<LogicalLine> lines;
    bool inBlockComment = false;
    std::size_t i = 0;
    while (i < physical.size()) {
        LogicalLine line;
        line.firstLine = static_cast<int>(i) + 1;
        line.startsInComment = inBlockComment;
        std::string spliced;
        bool continues = true;
        while (continues && i < physical.size()) {
            const std::string& current = physical[i++];
            line.physical.push_back(current);
            continues = endsWithContinuation(current);
            spliced += continues ? std::string_view(current).substr(0, current.size() - 1) : std::string_view(current);
        }
        line.code = blankComments(spliced, inBlockComment);
        line.endsInComment = inBlockComment;
        lines.push_back(std::move(line));
    }
    return lines;
}

std::string_view trim(std::string_view text) {
    const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
    return text;
}

std::vector<std::string> splitWhitespace(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        std::size_t end = i;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
        if (end > i) words.emplace_back(text.substr(i, end - i));
        i = end;
    }
    return words;
}

std::vector<std::string> blankedDirective(const LogicalLine& line) {
    std::vector<std::string> lines(line.physical.size());
    if (line.startsInComment) {
        const std::size_t hash = line.code.find('#');
        lines.front() = line.physical.front().substr(0, std::min(hash, line.physical.front().size()));
    }
    if (line.endsInComment) lines.back() += " /*";
    return lines;
}

std::size_t findWord(std::string_view text, std::string_view word) {
    for (auto pos = text.find(word); pos != std::string_view::npos; pos = text.find(word, pos + 1)) {
        const bool startOk = pos == 0 || !isIdentifierChar(text[pos - 1]);
        const bool endOk = pos + word.size() == text.size() || !isIdentifierChar(text[pos + word.size()]);
        if (startOk && endOk) return pos;
    }
    return std::string_view::npos;
}

bool expandsNoMacros(const Directive& directive) {
    const std::string& n = directive.name;
    return n == "pragma" || n == "extension" || n == "version" || n == "error";
}

bool isIdentifier(std::string_view text) {
    return !text.empty() && isIdentifierStart(text.front()) && std::all_of(text.begin(), text.end(), isIdentifierChar);
}

std::optional<Directive> parseDirective(const LogicalLine& line) {
    std::string_view code = trim(line.code);
    if (code.empty() || code.front() != '#') return std::nullopt;
    code = trim(code.substr(1));
    std::size_t nameEnd = 0;
    while (nameEnd < code.size() && isIdentifierChar(code[nameEnd])) ++nameEnd;
    return Directive{std::string(code.substr(0, nameEnd)), std::string(trim(code.substr(nameEnd)))};
}

// ---- versions ----------------------------------------------------------------------

std::string GlslVersion::effectiveProfile() const {
    if (isEs()) return "es";
    if (profile.empty()) return number >= 150 ? "core" : "";
    return profile;
}

std::string GlslVersion::directive() const {
    return "#version " + std::to_string(number) + (profile.empty() ? "" : " " + profile);
}

bool GlslVersion::sameAs(const GlslVersion& other) const {
    return number == other.number && effectiveProfile() == other.effectiveProfile();
}

std::optional<GlslVersion> parseVersionArgument(std::string_view argument) {
    const auto words = splitWhitespace(argument);
    if (words.empty() || words.size() > 2) return std::nullopt;
    GlslVersion version;
    const auto& digits = words[0];
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), version.number);
    if (error != std::errc() || end != digits.data() + digits.size() || version.number <= 0) return std::nullopt;
    if (words.size() == 2) {
        version.profile = words[1];
        if (version.profile != "core" && version.profile != "compatibility" && version.profile != "es")
            return std::nullopt;
    }
    return version;
}

std::optional<GlslVersion> parseVersionDirective(std::string_view line) {
    const auto lines = splitLogicalLines(line);
    if (lines.empty()) return std::nullopt;
    const auto directive = parseDirective(lines.front());
    if (!directive || directive->name != "version") return std::nullopt;
    return parseVersionArgument(directive->argument);
}

}  // namespace prism::shaderc
