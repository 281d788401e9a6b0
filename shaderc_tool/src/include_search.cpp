// Include search and the directive helpers (see include_search.hpp).
#include "include_search.hpp"

#include "did_you_mean.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>

namespace prism::shaderc {

std::optional<IncludeTarget> parseIncludeTarget(std::string_view argument) {
    if (argument.size() < 2) return std::nullopt;
    const char open = argument.front();
    if (open != '"' && open != '<') return std::nullopt;
    const char close = open == '"' ? '"' : '>';
    const std::size_t end = argument.find(close, 1);
    if (end == std::string_view::npos || end == 1) return std::nullopt;
    if (!trim(argument.substr(end + 1)).empty()) return std::nullopt;
    return IncludeTarget{std::string(argument.substr(1, end - 1)), open == '<'};
}

std::vector<SearchDir> includeSearchDirs(const IncludeTarget& target, const std::vector<std::string>& chain,
                                         const std::vector<std::string>& includeDirs, const std::string& baseDir) {
    std::vector<SearchDir> dirs;
    auto add = [&](std::string path, std::string role, bool ancestor = false) {
        if (std::none_of(dirs.begin(), dirs.end(), [&](const SearchDir& d) { return d.path == path; }))
            dirs.push_back({std::move(path), std::move(role), ancestor});
    };
    const bool rootRelative = target.name.starts_with('/');
    if (!target.angled && !rootRelative)
        for (std::size_t i = 0; i < chain.size(); ++i)
            add(parentDir(chain[i]), i == 0 ? "the including file's folder" : "folder of " + chain[i], i > 0);
    for (const auto& dir : includeDirs) add(joinPath("", dir), "-I");
    if (rootRelative && !baseDir.empty()) add(joinPath("", baseDir), "--base-dir");
    return dirs;
}

namespace {

// The paths an #include of `target` could have meant (the "did you mean" of "cannot find include"):
// files next to where each searched folder would have had it ("a/utl.glsl" -> the files of each
// dir/a/), as the include would spell them.
std::vector<std::string> includeCandidates(const IncludeTarget& target, const std::vector<SearchDir>& dirs) {
    namespace fs = std::filesystem;
    const std::string name = target.name;
    const auto slash = name.rfind('/');
    const std::string folder = slash == std::string::npos ? std::string() : name.substr(0, slash + 1);
    std::set<std::string> found;
    for (const auto& dir : dirs) {
        std::string relative = folder;
        while (!relative.empty() && relative.front() == '/') relative.erase(0, 1);  // "/lib/x": below the dir
        const fs::path where = fs::path(dir.path.empty() ? "." : dir.path) / relative;
        std::error_code ec;
        for (auto it = fs::directory_iterator(where, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
            if (it->is_regular_file(ec)) found.insert(folder + it->path().filename().string());
    }
    return {found.begin(), found.end()};
}

// The first file `target` names in dirs[from, end) that glslc would also search when
// `glslcOnly` (not an ancestor folder), other than `except` (a canonical path).
std::optional<FoundFile> findFrom(const IncludeTarget& target, const std::vector<SearchDir>& dirs, std::size_t from,
                                  const SourceReader& reader, bool glslcOnly = false, const std::string& except = "") {
    std::string_view name = target.name;
    while (name.starts_with('/')) name.remove_prefix(1);
    if (name.empty()) return std::nullopt;
    for (std::size_t i = from; i < dirs.size(); ++i) {
        if (glslcOnly && dirs[i].ancestor) continue;
        std::string display = joinPath(dirs[i].path, std::string(name));
        if (auto canonical = reader.canonical(display); canonical && *canonical != except)
            return FoundFile{std::move(display), *canonical, i};
    }
    return std::nullopt;
}

std::string placeOf(const FoundFile& file, const std::vector<SearchDir>& dirs) {
    return file.display + " (" + dirs[file.dir].role + ")";
}

}  // namespace

std::optional<FoundFile> findInclude(const IncludeTarget& target, const std::vector<SearchDir>& dirs,
                                     const SourceReader& reader) {
    return findFrom(target, dirs, 0, reader);
}

std::string shadowedIncludeMessage(const IncludeTarget& target, const std::vector<SearchDir>& dirs,
                                   const FoundFile& found, const SourceReader& reader) {
    const auto shadowed = findFrom(target, dirs, found.dir + 1, reader, false, found.canonical);
    if (!shadowed) return {};
    const std::string written = target.angled ? "<" + target.name + ">" : "\"" + target.name + "\"";
    std::string message = "#include " + written + " could mean " + placeOf(found, dirs) + " or " +
                          placeOf(*shadowed, dirs) + "; the first is used";
    const auto glslcPick = findFrom(target, dirs, 0, reader, true);
    if (glslcPick && glslcPick->canonical != found.canonical)
        message += ", but glslc (which skips the folders up the include chain) would take " + glslcPick->display;
    message += "; rename one of them, or write a path that only one folder holds";
    if (dirs[found.dir].ancestor) {  // dirs[0] is the including file's folder
        const std::string from = dirs[0].path.empty() ? "." : dirs[0].path;
        message += " (here \"" + std::filesystem::path(found.display).lexically_relative(from).generic_string() + "\")";
    }
    return message;
}

std::string missingIncludeMessage(const IncludeTarget& target, const std::vector<SearchDir>& dirs) {
    const std::string written = target.angled ? "<" + target.name + ">" : "\"" + target.name + "\"";
    const std::string hint = closestName(target.name, includeCandidates(target, dirs));
    std::string message =
        "cannot find include " + written +
        (hint.empty() ? "" : " (did you mean " + (target.angled ? "<" + hint + ">" : "\"" + hint + "\"") + "?)") +
        "; searched: ";
    if (dirs.empty()) message += "no directories (<...> and \"/...\" search only -I directories and --base-dir)";
    for (std::size_t i = 0; i < dirs.size(); ++i)
        message +=
            (i ? ", " : "") + (dirs[i].path.empty() ? std::string(".") : dirs[i].path) + " (" + dirs[i].role + ")";
    return message + "; add a -I directory or fix the path";
}

int directiveColumn(const LogicalLine& line) {
    const std::size_t at = line.code.find_first_not_of(" \t");
    return at == std::string::npos ? 1 : static_cast<int>(at) + 1;
}

int includeTargetColumn(const LogicalLine& line) {
    const std::string& code = line.code;
    const std::size_t keyword = code.find("include");
    const std::size_t quote = keyword == std::string::npos ? std::string::npos : code.find_first_of("\"<", keyword);
    if (quote == std::string::npos || quote >= line.physical.front().size()) return directiveColumn(line);
    return static_cast<int>(quote) + 1;
}

bool isPragmaOnce(const Directive& directive) {
    return directive.name == "pragma" && splitWhitespace(directive.argument) == std::vector<std::string>{"once"};
}

bool isPrismPragma(const Directive& directive) {
    const auto words = splitWhitespace(directive.argument);
    return directive.name == "pragma" && !words.empty() && words.front() == "prism";
}

bool isIncludeExtension(const Directive& directive) {
    static constexpr std::array<std::string_view, 3> kIncludeExtensions = {
        "GL_GOOGLE_include_directive", "GL_ARB_shading_language_include", "GL_GOOGLE_cpp_style_line_directive"};
    if (directive.name != "extension") return false;
    std::string_view argument = directive.argument;
    const std::string_view name = trim(argument.substr(0, argument.find(':')));
    return std::find(kIncludeExtensions.begin(), kIncludeExtensions.end(), name) != kIncludeExtensions.end();
}

}  // namespace prism::shaderc
