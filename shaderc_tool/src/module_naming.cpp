// Collision-free module identifiers from relative paths (see module_naming.hpp).
#include "module_naming.hpp"

#include <cctype>
#include <set>
#include <vector>

namespace prism::shaderc {
namespace {

bool isAlnum(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

// Letters and digits with single underscores between them; the first component
// must also start with a letter, so the identifier does.
bool isPlainComponent(std::string_view c, bool first) {
    if (c.empty() || !isAlnum(c.front()) || !isAlnum(c.back())) return false;
    if (first && std::isdigit(static_cast<unsigned char>(c.front()))) return false;
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (isAlnum(c[i])) continue;
        if (c[i] != '_' || c[i + 1] == '_') return false;  // c.back() is alnum, so i + 1 is valid
    }
    return true;
}

std::string hexOf(std::string_view bytes) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out;
    for (unsigned char b : bytes) {
        out += digits[b >> 4];
        out += digits[b & 15];
    }
    return out;
}

std::optional<std::string> bytesOfHex(std::string_view hex) {
    if (hex.empty() || hex.size() % 2 != 0) return std::nullopt;
    auto value = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        return -1;
    };
    std::string out;
    for (std::size_t i = 0; i < hex.size(); i += 2) {
        const int hi = value(hex[i]), lo = value(hex[i + 1]);
        if (hi < 0 || lo < 0) return std::nullopt;
        out += static_cast<char>(hi * 16 + lo);
    }
    return out;
}

const std::set<std::string, std::less<>>& cppKeywords() {
    static const std::set<std::string, std::less<>> words = {
        "alignas",     "alignof",   "and",        "and_eq",    "asm",      "auto",         "bitand",
        "bitor",       "bool",      "break",      "case",      "catch",    "char",         "char8_t",
        "char16_t",    "char32_t",  "class",      "compl",     "concept",  "const",        "consteval",
        "constexpr",   "constinit", "const_cast", "continue",  "co_await", "co_return",    "co_yield",
        "decltype",    "default",   "delete",     "do",        "double",   "dynamic_cast", "else",
        "enum",        "explicit",  "export",     "extern",    "false",    "float",        "for",
        "friend",      "goto",      "if",         "inline",    "int",      "long",         "mutable",
        "namespace",   "new",       "noexcept",   "not",       "not_eq",   "nullptr",      "operator",
        "or",          "or_eq",     "private",    "protected", "public",   "register",     "reinterpret_cast",
        "requires",    "return",    "short",      "signed",    "sizeof",   "static",       "static_assert",
        "static_cast", "struct",    "switch",     "template",  "this",     "thread_local", "throw",
        "true",        "try",       "typedef",    "typeid",    "typename", "union",        "unsigned",
        "using",       "virtual",   "void",       "volatile",  "wchar_t",  "while",        "xor",
        "xor_eq",      "module",    "import"};
    return words;
}

// The identifier piece of one component: itself when plain, else "_" + hex. The last
// component is a file name: plain only as "<plain>.glsl", written without ".glsl".
std::string pieceOf(std::string_view component, bool first, bool last) {
    constexpr std::string_view kExtension = ".glsl";
    if (last) {
        if (component.ends_with(kExtension)) {
            const std::string_view stem = component.substr(0, component.size() - kExtension.size());
            if (isPlainComponent(stem, first)) return std::string(stem);
        }
    } else if (isPlainComponent(component, first)) {
        return std::string(component);
    }
    return "_" + hexOf(component);
}

}  // namespace

std::string mangleModulePath(std::string_view relativePath) {
    std::vector<std::string_view> components;
    std::size_t start = 0;
    while (start <= relativePath.size()) {
        std::size_t end = relativePath.find_first_of("/\\", start);
        if (end == std::string_view::npos) end = relativePath.size();
        components.push_back(relativePath.substr(start, end - start));
        start = end + 1;
    }
    std::string id;
    for (std::size_t i = 0; i < components.size(); ++i)
        id += (i ? "__" : "") + pieceOf(components[i], i == 0, i + 1 == components.size());
    if (isCppKeyword(id)) id += '_';
    return id;
}

std::optional<std::string> demangleModuleIdentifier(std::string_view id) {
    if (id.empty()) return std::nullopt;
    const bool keywordSuffix = id.back() == '_';  // nothing else ends in '_'
    if (keywordSuffix) {
        id.remove_suffix(1);
        if (!isCppKeyword(id)) return std::nullopt;
    }
    std::vector<std::pair<std::string_view, bool>> pieces;  // text, hex
    std::size_t i = 0;
    while (true) {
        const bool hex = i < id.size() && id[i] == '_';  // '_' right at a piece's start marks hex
        const std::size_t begin = hex ? i + 1 : i;
        std::size_t end = id.find("__", begin);
        if (end == std::string_view::npos) end = id.size();
        pieces.emplace_back(id.substr(begin, end - begin), hex);
        if (end == id.size()) break;
        i = end + 2;
    }
    std::string path;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const auto [text, hex] = pieces[k];
        const bool first = k == 0, last = k + 1 == pieces.size();
        std::string component;
        if (hex) {
            auto bytes = bytesOfHex(text);
            if (!bytes) return std::nullopt;
            component = *bytes;
        } else {
            if (!isPlainComponent(text, first)) return std::nullopt;
            component = std::string(text) + (last ? ".glsl" : "");
        }
        if (component.empty() || component.find_first_of("/\\") != std::string::npos) return std::nullopt;
        if (pieceOf(component, first, last) != (hex ? "_" : "") + std::string(text)) return std::nullopt;
        path += (first ? "" : "/") + component;
    }
    // Only an identifier that mangling itself writes has a path.
    if (mangleModulePath(path) != std::string(id) + (keywordSuffix ? "_" : "")) return std::nullopt;
    return path;
}

std::string mangleName(std::string_view name) {
    std::string id = pieceOf(name, true, false);
    if (isCppKeyword(id)) id += '_';
    return id;
}

std::optional<std::string> demangleName(std::string_view id) {
    if (id.empty()) return std::nullopt;
    std::string name(id);
    if (id.back() == '_' && isCppKeyword(id.substr(0, id.size() - 1))) {
        name.pop_back();
    } else if (id.front() == '_') {
        auto bytes = bytesOfHex(id.substr(1));
        if (!bytes) return std::nullopt;
        name = *bytes;
    }
    if (name.empty() || mangleName(name) != id) return std::nullopt;
    return name;
}

bool isCppKeyword(std::string_view word) {
    return cppKeywords().contains(word);
}

std::string cppIdentifier(const std::string& name) {
    std::string id;
    for (char c : name) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "_" + id;
    if (isCppKeyword(id)) id += '_';
    return id;
}

}  // namespace prism::shaderc
