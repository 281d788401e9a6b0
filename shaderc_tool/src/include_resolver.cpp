// Stage 2 of prism-shaderc: flattens a stage file and its #includes into one
// driver-safe GLSL text with true `#line` numbers, and scans modules for the
// catalogue (see include_resolver.hpp for the rules).
#include "include_resolver.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string_view>
#include <variant>

#include "preprocessor_conditions.hpp"

namespace prism::shaderc {
namespace {

constexpr std::size_t kMaxIncludeDepth = 64;

// Extensions that only make sense to an include-aware front end; a GL driver may
// reject them, and the output needs none of them.
constexpr std::array<std::string_view, 3> kIncludeExtensions = {
    "GL_GOOGLE_include_directive", "GL_ARB_shading_language_include", "GL_GOOGLE_cpp_style_line_directive"};

// ---- directive helpers ---------------------------------------------------------------

struct IncludeTarget {
    std::string name;
    bool angled = false;  // <name>: include dirs only
};

// `"name"` or `<name>` with nothing after it; nullopt when malformed.
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

// 1-based column of the first non-blank character of the line (the '#').
int directiveColumn(const LogicalLine& line) {
    const std::string& first = line.physical.front();
    const std::size_t at = first.find_first_not_of(" \t");
    return at == std::string::npos ? 1 : static_cast<int>(at) + 1;
}

// 1-based column of the quote or '<' opening the include target, when it is on the
// directive's first physical line; else the directive's column.
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
    if (directive.name != "extension") return false;
    std::string_view argument = directive.argument;
    const std::string_view name = trim(argument.substr(0, argument.find(':')));
    return std::find(kIncludeExtensions.begin(), kIncludeExtensions.end(), name) != kIncludeExtensions.end();
}

// Lines never passed on to the compiler, active or not.
bool isAlwaysBlanked(const Directive& directive) {
    return directive.name == "include" || directive.name == "version" || isPragmaOnce(directive) ||
           isPrismPragma(directive) || isIncludeExtension(directive);
}

// ---- include search ------------------------------------------------------------------

struct FoundFile {
    std::string display;
    std::string canonical;
};

struct SearchDir {
    std::string path;
    bool includerDir = false;
};

std::vector<SearchDir> searchDirs(const IncludeTarget& target, const std::string& includerPath,
                                  const ResolveOptions& options) {
    std::vector<SearchDir> dirs;
    if (!target.angled) dirs.push_back({parentDir(includerPath), true});
    for (const auto& dir : options.includeDirs) dirs.push_back({dir, false});
    return dirs;
}

std::optional<FoundFile> findInclude(const IncludeTarget& target, const std::vector<SearchDir>& dirs,
                                     const SourceReader& reader) {
    for (const auto& dir : dirs) {
        std::string display = joinPath(dir.path, target.name);
        if (auto canonical = reader.canonical(display)) return FoundFile{std::move(display), *canonical};
    }
    return std::nullopt;
}

std::string describeDir(const SearchDir& dir) {
    const std::string shown = dir.path.empty() ? "." : dir.path;
    return dir.includerDir ? shown + " (the including file's directory)" : shown;
}

std::string missingIncludeMessage(const IncludeTarget& target, const std::vector<SearchDir>& dirs) {
    const std::string written = target.angled ? "<" + target.name + ">" : "\"" + target.name + "\"";
    std::string message = "cannot find include " + written + "; searched: ";
    if (dirs.empty()) message += "no directories (<...> searches only -I directories)";
    for (std::size_t i = 0; i < dirs.size(); ++i) message += (i ? ", " : "") + describeDir(dirs[i]);
    return message + "; add a -I directory or fix the path";
}

// ---- diagnostics -----------------------------------------------------------------------

Diagnostic makeDiagnostic(Severity severity, std::string file, int line, int column, std::string message,
                          std::vector<IncludeSite> includedFrom = {}) {
    Diagnostic d = makeError(std::move(file), line, column, std::move(message));
    d.severity = severity;
    d.includedFrom = std::move(includedFrom);
    return d;
}

Diagnostic makeNote(std::string file, int line, std::string message) {
    return makeDiagnostic(Severity::Note, std::move(file), line, 0, std::move(message));
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::string placeName(const std::string& file, int line) {
    return file + ":" + std::to_string(line);
}

// ---- variants --------------------------------------------------------------------------

bool isVariantValue(std::string_view value) {
    if (isIdentifier(value)) return true;
    if (value.starts_with('-')) value.remove_prefix(1);
    return !value.empty() && std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Checks the words after `#pragma prism variant`; returns an error message or "".
std::string checkVariantDeclaration(const std::vector<std::string>& words) {
    if (words.empty()) return "#pragma prism variant needs a name: #pragma prism variant NAME [values...]";
    if (!isIdentifier(words[0])) return "invalid variant name '" + words[0] + "' (must be an identifier)";
    std::set<std::string> seen;
    for (std::size_t i = 1; i < words.size(); ++i) {
        if (!isVariantValue(words[i]))
            return "invalid value '" + words[i] + "' of variant " + words[0] + " (must be an identifier or an integer)";
        if (!seen.insert(words[i]).second) return "value '" + words[i] + "' listed twice for variant " + words[0];
    }
    return {};
}

std::string joinWords(const std::vector<std::string>& words) {
    std::string joined;
    for (const auto& word : words) joined += (joined.empty() ? "" : " ") + word;
    return joined;
}

// ---- the stage resolver --------------------------------------------------------------

struct LineMarker {
    int nextLine = 1;  // true number of the next output line in `source`
    std::uint32_t source = 0;
};

using OutputPiece = std::variant<std::string, LineMarker>;

struct SeenVersion {
    GlslVersion version;
    std::string file;
    int line = 0;
};

class StageResolver {
  public:
    StageResolver(const ResolveOptions& options, const SourceReader& reader) : options_(options), reader_(reader) {}

    ResolveResult resolve(const std::string& stagePath);

  private:
    struct Frame {
        std::uint32_t number = 0;
        std::string display;
        std::string canonical;
        std::vector<IncludeSite> chain;
    };

    void applyOptions();
    void processFile(const Frame& frame, const std::string& text);
    void handleActiveDirective(const Frame& frame, const LogicalLine& line, const Directive& directive);
    void handleInclude(const Frame& frame, const LogicalLine& line, const Directive& directive);
    std::optional<FoundFile> locateInclude(const Frame& frame, const LogicalLine& line, const Directive& directive);
    void enterInclude(const Frame& includer, const LogicalLine& line, const FoundFile& found);
    std::optional<std::string> cycleThrough(const FoundFile& found) const;
    void handleVersion(const Frame& frame, const LogicalLine& line, const Directive& directive);
    void handlePragma(const Frame& frame, const LogicalLine& line, const Directive& directive);
    void handleVariant(const Frame& frame, const LogicalLine& line, const std::vector<std::string>& words);
    void handleUndef(const Frame& frame, const LogicalLine& line, const Directive& directive);

    Diagnostic& report(Severity severity, const Frame& frame, int line, int column, std::string message);
    void emitCopy(const LogicalLine& line);
    void emitBlank(const LogicalLine& line);
    GlslVersion finalVersion() const;
    std::string render() const;

    const ResolveOptions& options_;
    const SourceReader& reader_;
    MacroTable macros_;
    GlslVersion defaultVersion_{330, "core"};
    std::optional<SeenVersion> version_;
    std::vector<const Frame*> stack_;  // files being processed, outermost first
    std::set<std::string> entered_;    // canonical paths
    std::vector<OutputPiece> body_;
    ResolveResult result_;
};

ResolveResult StageResolver::resolve(const std::string& stagePath) {
    applyOptions();
    Frame stage;
    stage.display = joinPath("", stagePath);
    const auto canonical = reader_.canonical(stage.display);
    const auto text = canonical ? reader_.read(stage.display) : std::nullopt;
    if (!text) {
        result_.diagnostics.push_back(
            makeError(stage.display, 0, 0, canonical ? "cannot read the stage file" : "stage file not found"));
        return std::move(result_);
    }
    stage.canonical = *canonical;
    entered_.insert(stage.canonical);
    result_.stage.files.push_back({0, stage.display, stage.canonical, {}});
    result_.stage.filesRead.push_back(stage.display);

    body_.emplace_back(LineMarker{1, 0});
    stack_.push_back(&stage);
    processFile(stage, *text);
    stack_.pop_back();

    const GlslVersion version = finalVersion();
    result_.stage.versionDirective = version.directive();
    result_.stage.versionNumber = version.number;
    result_.stage.text = render();
    result_.ok = !hasErrors(result_.diagnostics);
    return std::move(result_);
}

void StageResolver::applyOptions() {
    if (auto parsed = parseVersionDirective(options_.defaultVersion))
        defaultVersion_ = *parsed;
    else
        result_.diagnostics.push_back(
            makeError("", 0, 0, "invalid default version directive '" + options_.defaultVersion + "'"));
    predefineVersionMacros(macros_, defaultVersion_);
    for (const auto& [name, value] : options_.defines) {
        if (!isIdentifier(name) || value.find_first_of("\r\n") != std::string::npos)
            result_.diagnostics.push_back(makeError("", 0, 0, "invalid define '" + name + "=" + value + "'"));
        else
            macros_.define(name, value);
    }
}

void StageResolver::processFile(const Frame& frame, const std::string& text) {
    ConditionalStack conditions;
    for (const LogicalLine& line : splitLogicalLines(text)) {
        const auto directive = parseDirective(line);
        if (!directive) {
            emitCopy(line);
        } else if (isConditionalDirective(directive->name)) {
            if (auto message = conditions.apply(*directive, line.firstLine, macros_); !message.empty())
                report(Severity::Error, frame, line.firstLine, directiveColumn(line), std::move(message));
            emitCopy(line);
        } else if (!conditions.active()) {
            isAlwaysBlanked(*directive) ? emitBlank(line) : emitCopy(line);
        } else {
            handleActiveDirective(frame, line, *directive);
        }
    }
    if (const auto open = conditions.innermostOpen())
        report(Severity::Error, frame, open->line, 0,
               "unterminated #" + open->directive + ": no matching #endif before the end of the file");
}

void StageResolver::handleActiveDirective(const Frame& frame, const LogicalLine& line, const Directive& directive) {
    if (directive.name == "include") return handleInclude(frame, line, directive);
    if (directive.name == "version") return handleVersion(frame, line, directive);
    if (directive.name == "pragma") return handlePragma(frame, line, directive);
    if (directive.name == "undef") return handleUndef(frame, line, directive);
    if (directive.name == "define") {
        if (auto message = macros_.defineFromDirective(directive.argument); !message.empty())
            report(Severity::Error, frame, line.firstLine, directiveColumn(line), std::move(message));
    }
    isIncludeExtension(directive) ? emitBlank(line) : emitCopy(line);
}

void StageResolver::handleInclude(const Frame& frame, const LogicalLine& line, const Directive& directive) {
    if (const auto found = locateInclude(frame, line, directive))
        enterInclude(frame, line, *found);
    else
        emitBlank(line);
}

// The file an active #include brings in, or nullopt (after reporting any error) when
// the line is not followed: malformed, missing, a cycle, too deep, or entered before.
std::optional<FoundFile> StageResolver::locateInclude(const Frame& frame, const LogicalLine& line,
                                                      const Directive& directive) {
    const auto target = parseIncludeTarget(directive.argument);
    if (!target) {
        report(Severity::Error, frame, line.firstLine, directiveColumn(line),
               "malformed #include: expected #include \"file\" or #include <file>");
        return std::nullopt;
    }
    const auto dirs = searchDirs(*target, frame.display, options_);
    auto found = findInclude(*target, dirs, reader_);
    if (!found) {
        report(Severity::Error, frame, line.firstLine, includeTargetColumn(line), missingIncludeMessage(*target, dirs));
        return std::nullopt;
    }
    if (auto cycle = cycleThrough(*found)) {
        report(Severity::Error, frame, line.firstLine, includeTargetColumn(line), "include cycle: " + *cycle);
        return std::nullopt;
    }
    if (entered_.contains(found->canonical)) return std::nullopt;  // every file enters a stage once
    if (stack_.size() >= kMaxIncludeDepth) {
        report(Severity::Error, frame, line.firstLine, includeTargetColumn(line),
               "includes nested more than " + std::to_string(kMaxIncludeDepth) + " deep at " + found->display);
        return std::nullopt;
    }
    return found;
}

void StageResolver::enterInclude(const Frame& includer, const LogicalLine& line, const FoundFile& found) {
    const int nextIncluderLine = line.firstLine + static_cast<int>(line.physical.size());
    Frame child;
    child.number = static_cast<std::uint32_t>(result_.stage.files.size());
    child.display = found.display;
    child.canonical = found.canonical;
    child.chain.push_back({includer.display, line.firstLine});
    child.chain.insert(child.chain.end(), includer.chain.begin(), includer.chain.end());
    entered_.insert(child.canonical);

    const auto text = reader_.read(child.display);
    if (!text) {
        report(Severity::Error, includer, line.firstLine, includeTargetColumn(line),
               "cannot read include file " + child.display);
        emitBlank(line);
        return;
    }
    result_.stage.files.push_back({child.number, child.display, child.canonical, child.chain});
    result_.stage.filesRead.push_back(child.display);

    body_.emplace_back(LineMarker{1, child.number});
    stack_.push_back(&child);
    processFile(child, *text);
    stack_.pop_back();
    body_.emplace_back(LineMarker{nextIncluderLine, includer.number});
}

// "a.glsl -> b.glsl -> a.glsl" when `found` is already being processed.
std::optional<std::string> StageResolver::cycleThrough(const FoundFile& found) const {
    const auto first = std::find_if(stack_.begin(), stack_.end(),
                                    [&](const Frame* frame) { return frame->canonical == found.canonical; });
    if (first == stack_.end()) return std::nullopt;
    std::string chain;
    for (auto it = first; it != stack_.end(); ++it) chain += (*it)->display + " -> ";
    return chain + found.display;
}

void StageResolver::handleVersion(const Frame& frame, const LogicalLine& line, const Directive& directive) {
    emitBlank(line);  // the version is hoisted to line 1
    const auto version = parseVersionArgument(directive.argument);
    if (!version) {
        report(Severity::Error, frame, line.firstLine, directiveColumn(line),
               "malformed #version: expected e.g. #version 330 core");
        return;
    }
    if (!version_) {
        version_ = SeenVersion{*version, frame.display, line.firstLine};
        predefineVersionMacros(macros_, *version);
        return;
    }
    if (version_->version.sameAs(*version)) return;
    auto& error =
        report(Severity::Error, frame, line.firstLine, directiveColumn(line),
               version->directive() + " conflicts with " + version_->version.directive() + " at " +
                   placeName(version_->file, version_->line) + "; all files of a stage must ask for the same version");
    error.notes.push_back(makeNote(version_->file, version_->line, "first #version is here"));
}

void StageResolver::handlePragma(const Frame& frame, const LogicalLine& line, const Directive& directive) {
    const auto words = splitWhitespace(directive.argument);
    if (isPragmaOnce(directive)) return emitBlank(line);  // every file enters once anyway
    if (!isPrismPragma(directive)) return emitCopy(line);
    emitBlank(line);
    if (words.size() >= 2 && words[1] == "variant")
        return handleVariant(frame, line, std::vector<std::string>(words.begin() + 2, words.end()));
    report(Severity::Warning, frame, line.firstLine, directiveColumn(line),
           "unknown #pragma prism '" + (words.size() >= 2 ? words[1] : std::string()) + "' ignored (known: variant)");
}

void StageResolver::handleVariant(const Frame& frame, const LogicalLine& line, const std::vector<std::string>& words) {
    if (auto message = checkVariantDeclaration(words); !message.empty()) {
        report(Severity::Error, frame, line.firstLine, directiveColumn(line), std::move(message));
        return;
    }
    const std::vector<std::string> values(words.begin() + 1, words.end());
    auto& pragmas = result_.stage.variantPragmas;
    const auto earlier =
        std::find_if(pragmas.begin(), pragmas.end(), [&](const VariantPragma& p) { return p.name == words[0]; });
    if (earlier == pragmas.end()) {
        pragmas.push_back({words[0], values, frame.display, line.firstLine});
        return;
    }
    if (earlier->values == values) return;  // the same declaration in another module: merged
    auto& error = report(Severity::Error, frame, line.firstLine, directiveColumn(line),
                         "variant " + words[0] + " declared with values {" + joinWords(values) + "} here but {" +
                             joinWords(earlier->values) + "} at " + placeName(earlier->file, earlier->line));
    error.notes.push_back(makeNote(earlier->file, earlier->line, "variant " + words[0] + " first declared here"));
}

void StageResolver::handleUndef(const Frame& frame, const LogicalLine& line, const Directive& directive) {
    const auto words = splitWhitespace(directive.argument);
    if (words.empty() || !isIdentifier(words[0]))
        report(Severity::Error, frame, line.firstLine, directiveColumn(line), "#undef needs a macro name");
    else
        macros_.undefine(words[0]);
    emitCopy(line);
}

Diagnostic& StageResolver::report(Severity severity, const Frame& frame, int line, int column, std::string message) {
    result_.diagnostics.push_back(
        makeDiagnostic(severity, frame.display, line, column, std::move(message), frame.chain));
    return result_.diagnostics.back();
}

void StageResolver::emitCopy(const LogicalLine& line) {
    body_.insert(body_.end(), line.physical.begin(), line.physical.end());
}

void StageResolver::emitBlank(const LogicalLine& line) {
    body_.insert(body_.end(), line.physical.size(), std::string());
}

GlslVersion StageResolver::finalVersion() const {
    return version_ ? version_->version : defaultVersion_;
}

// Line 1 the version, then the -D defines, then the body. Since GLSL 3.30 (and in
// GLSL ES) the line after `#line N` is line N; before 3.30 it is line N + 1.
std::string StageResolver::render() const {
    const GlslVersion version = finalVersion();
    const bool lineDirectiveNamesNextLine = version.isEs() || version.number >= 330;
    std::string text = version.directive() + "\n";
    for (const auto& [name, value] : options_.defines)
        text += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
    for (const auto& piece : body_) {
        if (const auto* marker = std::get_if<LineMarker>(&piece)) {
            const int number = lineDirectiveNamesNextLine ? marker->nextLine : marker->nextLine - 1;
            text += "#line " + std::to_string(number) + " " + std::to_string(marker->source) + "\n";
        } else {
            text += std::get<std::string>(piece) + "\n";
        }
    }
    return text;
}

// ---- module scanning -----------------------------------------------------------------

// The text of a comment line after its `//`, `///` or `//!` marker.
std::string_view lineCommentText(std::string_view line) {
    line = trim(line);
    while (line.starts_with('/')) line.remove_prefix(1);
    if (line.starts_with('!')) line.remove_prefix(1);
    return trim(line);
}

// One line inside a /* */ block without its decoration (leading '*'s).
std::string_view blockCommentLineText(std::string_view line) {
    line = trim(line);
    while (line.starts_with('*') && !line.starts_with("*/")) line.remove_prefix(1);
    return trim(line);
}

void appendWords(std::string& out, std::string_view text) {
    if (text.empty()) return;
    if (!out.empty()) out += ' ';
    out += text;
}

bool isSkippedBeforeDescription(const LogicalLine& line) {
    if (line.startsInComment) return false;
    const auto directive = parseDirective(line);
    if (directive) return directive->name == "version" || isPragmaOnce(*directive);
    return trim(line.physical.front()).empty() && line.physical.size() == 1;
}

std::string leadingComment(const std::vector<LogicalLine>& lines) {
    std::vector<std::string> physical;
    auto start = std::find_if_not(lines.begin(), lines.end(), isSkippedBeforeDescription);
    for (auto it = start; it != lines.end(); ++it)
        physical.insert(physical.end(), it->physical.begin(), it->physical.end());

    std::string description;
    if (physical.empty()) return description;
    if (trim(physical.front()).starts_with("//")) {
        for (const auto& line : physical) {
            if (!trim(line).starts_with("//")) break;
            appendWords(description, lineCommentText(line));
        }
    } else if (trim(physical.front()).starts_with("/*")) {
        physical.front() = std::string(trim(physical.front()).substr(2));
        for (const auto& line : physical) {
            const std::size_t end = line.find("*/");
            appendWords(description, blockCommentLineText(std::string_view(line).substr(0, end)));
            if (end != std::string::npos) break;
        }
    }
    return description;
}

class ModuleScanner {
  public:
    ModuleScanner(const ResolveOptions& options, const SourceReader& reader) : options_(options), reader_(reader) {}

    ModuleScanResult scan(const std::string& modulePath);

  private:
    void scanLines(const std::vector<LogicalLine>& lines);
    void addInclude(const LogicalLine& line, const Directive& directive);
    void trackDefinition(const Directive& directive);
    void report(Severity severity, int line, int column, std::string message);

    const ResolveOptions& options_;
    const SourceReader& reader_;
    MacroTable macros_;
    std::vector<std::string> textLines_;
    std::set<std::string> includedCanonicals_;
    ModuleScanResult result_;
};

ModuleScanResult ModuleScanner::scan(const std::string& modulePath) {
    ModuleSource& module = result_.module;
    module.path = joinPath("", modulePath);
    const auto canonical = reader_.canonical(module.path);
    const auto text = canonical ? reader_.read(module.path) : std::nullopt;
    if (!text) {
        report(Severity::Error, 0, 0, canonical ? "cannot read the module" : "module not found");
        return std::move(result_);
    }
    module.canonical = *canonical;
    predefineVersionMacros(macros_, parseVersionDirective(options_.defaultVersion).value_or(GlslVersion{330, "core"}));
    for (const auto& [name, value] : options_.defines) macros_.define(name, value);

    const auto lines = splitLogicalLines(*text);
    scanLines(lines);
    for (const auto& line : textLines_) module.text += line + "\n";
    module.description = leadingComment(lines);
    if (module.description.empty())
        report(Severity::Warning, 1, 0, "module has no leading comment saying what it provides");
    result_.ok = !hasErrors(result_.diagnostics);
    return std::move(result_);
}

void ModuleScanner::scanLines(const std::vector<LogicalLine>& lines) {
    ConditionalStack conditions;
    for (const LogicalLine& line : lines) {
        const auto directive = parseDirective(line);
        const bool blank = directive && (directive->name == "include" || directive->name == "version" ||
                                         isPragmaOnce(*directive) || isIncludeExtension(*directive));
        if (blank)
            textLines_.insert(textLines_.end(), line.physical.size(), std::string());
        else
            textLines_.insert(textLines_.end(), line.physical.begin(), line.physical.end());
        if (!directive) continue;
        if (isConditionalDirective(directive->name)) {
            if (auto message = conditions.apply(*directive, line.firstLine, macros_); !message.empty())
                report(Severity::Error, line.firstLine, directiveColumn(line), std::move(message));
        } else if (conditions.active() && directive->name == "include") {
            addInclude(line, *directive);
        } else if (conditions.active()) {
            trackDefinition(*directive);
        }
    }
    if (const auto open = conditions.innermostOpen())
        report(Severity::Error, open->line, 0,
               "unterminated #" + open->directive + ": no matching #endif before the end of the file");
}

void ModuleScanner::addInclude(const LogicalLine& line, const Directive& directive) {
    const auto target = parseIncludeTarget(directive.argument);
    if (!target) {
        report(Severity::Error, line.firstLine, directiveColumn(line),
               "malformed #include: expected #include \"file\" or #include <file>");
        return;
    }
    const auto dirs = searchDirs(*target, result_.module.path, options_);
    const auto found = findInclude(*target, dirs, reader_);
    if (!found) {
        report(Severity::Error, line.firstLine, includeTargetColumn(line), missingIncludeMessage(*target, dirs));
        return;
    }
    if (includedCanonicals_.insert(found->canonical).second) result_.module.includes.push_back(found->display);
}

void ModuleScanner::trackDefinition(const Directive& directive) {
    const auto words = splitWhitespace(directive.argument);
    if (directive.name == "define")
        macros_.defineFromDirective(directive.argument);
    else if (directive.name == "undef" && !words.empty())
        macros_.undefine(words[0]);
    else if (directive.name == "version")
        if (const auto version = parseVersionArgument(directive.argument)) predefineVersionMacros(macros_, *version);
}

void ModuleScanner::report(Severity severity, int line, int column, std::string message) {
    result_.diagnostics.push_back(makeDiagnostic(severity, result_.module.path, line, column, std::move(message)));
}

}  // namespace

ResolveResult resolveStage(const std::string& stagePath, const ResolveOptions& options, const SourceReader& reader) {
    return StageResolver(options, reader).resolve(stagePath);
}

ModuleScanResult scanModule(const std::string& modulePath, const ResolveOptions& options, const SourceReader& reader) {
    return ModuleScanner(options, reader).scan(modulePath);
}

}  // namespace prism::shaderc
