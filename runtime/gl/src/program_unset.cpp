// A Program's record of what was set since link, for the unset-uniform report
// (Program::unsetUniforms), and of the typed handles this variant compiled out. A uniform
// nobody set reads 0, which renders plausibly wrong (a black torus) instead of failing.
#include <algorithm>
#include <atomic>
#include <cctype>

#include "prism/gl/program.hpp"
#include "uniform_gl_types.hpp"

namespace prism::gl {
namespace {

#ifdef NDEBUG
std::atomic<bool> gDefaultUnsetCheck{false};
#else
std::atomic<bool> gDefaultUnsetCheck{true};
#endif

bool isWordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The next identifier at or after `i` (skipping blanks), moving `i` past it.
std::string_view nextWord(std::string_view text, std::size_t& i) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t start = i;
    while (i < text.size() && isWordChar(text[i])) ++i;
    return text.substr(start, i - start);
}

// Names declared `uniform [precision] <type> <name> [array] = ...` in `source`.
void collectInitialised(std::string_view source, std::set<std::string, std::less<>>& out) {
    constexpr std::string_view keyword = "uniform";
    for (std::size_t at = source.find(keyword); at != std::string_view::npos; at = source.find(keyword, at + 1)) {
        if ((at > 0 && isWordChar(source[at - 1])) ||
            (at + keyword.size() < source.size() && isWordChar(source[at + keyword.size()])))
            continue;
        std::size_t i = at + keyword.size();
        std::string_view type = nextWord(source, i);
        if (type == "lowp" || type == "mediump" || type == "highp") type = nextWord(source, i);
        const std::string_view name = nextWord(source, i);
        if (type.empty() || name.empty()) continue;
        while (i < source.size() && std::isspace(static_cast<unsigned char>(source[i]))) ++i;
        if (i < source.size() && source[i] == '[') i = source.find(']', i) + 1;
        while (i > 0 && i < source.size() && std::isspace(static_cast<unsigned char>(source[i]))) ++i;
        if (i > 0 && i < source.size() && source[i] == '=') out.emplace(name);
    }
}

}  // namespace

void setDefaultUnsetUniformCheck(bool on) {
    gDefaultUnsetCheck = on;
}

void Program::startUnsetCheck(const std::vector<StageText>& stages) {
    initialised_.clear();
    for (const auto& stage : stages) collectInitialised(stage.source, initialised_);
    setSinceLink_.clear();
    unsetReported_.clear();
    checkUnset_ = gDefaultUnsetCheck;
}

bool Program::compiledIn(std::string_view name) {
    if (uniforms_.find(name) != uniforms_.end()) return true;
    if (std::find(compiledOut_.begin(), compiledOut_.end(), name) == compiledOut_.end())
        compiledOut_.emplace_back(name);
    return false;
}

std::vector<std::string> Program::unsetUniforms() const {
    std::vector<std::string> out;
    for (const auto& u : declared_) {
        if (detail::isSamplerType(u.glType) || initialised_.count(u.name) || setSinceLink_.count(u.name)) continue;
        if (auto it = uniforms_.find(u.name); it == uniforms_.end() || it->second.location < 0) continue;
        out.push_back(u.name);
    }
    return out;
}

void Program::reportUnsetUniforms() const {
    if (!checkUnset_) return;
    for (const auto& name : unsetUniforms())
        if (unsetReported_.emplace(name).second)
            warn("uniform '" + name +
                 "' is active but was never set since the program was linked, so it reads 0; "
                 "set it before drawing, or give it an initialiser in GLSL. Reported once.");
}

}  // namespace prism::gl
