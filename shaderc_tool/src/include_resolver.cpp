// Part of stage 4 (catalog_builder.hpp): flattens a stage file and the #includes glslang's
// preprocessor follows into one driver-safe GLSL text with true `#line` numbers, and
// scans modules for the catalogue (see include_resolver.hpp for the rules).
#include "include_resolver.hpp"

#include <prism/catalog/line_directive.hpp>

#include <algorithm>
#include <array>
#include <regex>
#include <memory>
#include <optional>
#include <set>
#include <string_view>
#include <variant>

#include "include_search.hpp"
#include "preprocessor_limits.hpp"

namespace prism::shaderc {
namespace {

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

// The #version glslang is told to assume on a first run: the stage's own, when a
// #version is its first directive, else the default.
std::optional<GlslVersion> leadingVersion(const std::string& path, const SourceReader& reader) {
    const auto text = reader.read(joinPath("", path));
    if (!text) return std::nullopt;
    for (const auto& line : splitLogicalLines(*text)) {
        const auto directive = parseDirective(line);
        if (directive) return directive->name == "version" ? parseVersionArgument(directive->argument) : std::nullopt;
        if (!trim(line.code).empty()) return std::nullopt;
    }
    return std::nullopt;
}

// The macros of the include extensions: glslang defines them while it preprocesses
// (include support is always on), but the driver-safe output cannot define a GL_ name.
constexpr std::array<std::string_view, 2> kIncludeExtensionMacros = {"GL_GOOGLE_include_directive",
                                                                     "GL_GOOGLE_cpp_style_line_directive"};

// A conditional line testing an include-extension macro, rewritten so the driver takes
// the branch glslang took: `#ifdef M` -> `#if 1`, `#ifndef M` -> `#if 0`, and in
// #if/#elif `defined(M)`, `defined M` and `M` -> 1. nullopt when nothing to rewrite.
std::optional<std::vector<std::string>> withIncludeMacrosDefined(const LogicalLine& line, const Directive& directive) {
    const bool condition =
        directive.name == "if" || directive.name == "elif" || directive.name == "ifdef" || directive.name == "ifndef";
    if (!condition || line.physical.size() != 1) return std::nullopt;
    std::string text = line.physical.front();
    bool changed = false;
    for (const auto macro : kIncludeExtensionMacros) {
        if (text.find(macro) == std::string::npos) continue;
        changed = true;
        const std::string name(macro);
        if (directive.name == "ifdef" || directive.name == "ifndef") {
            if (trim(directive.argument) != macro) return std::nullopt;
            const std::size_t hash = line.code.find('#');
            text = text.substr(0, hash) + (directive.name == "ifdef" ? "#if 1" : "#if 0") +
                   (line.endsInComment ? " /*" : "");
            break;
        }
        text = std::regex_replace(text, std::regex(R"(defined\s*\(\s*)" + name + R"(\s*\))"), "1");
        text = std::regex_replace(text, std::regex(R"(defined\s+)" + name + R"(\b)"), "1");
        text = std::regex_replace(text, std::regex(R"(\b)" + name + R"(\b)"), "1");
    }
    if (!changed) return std::nullopt;
    return std::vector<std::string>{text};
}

// Walks the files of one preprocessing run in include order and writes the output.
class Flattener {
  public:
    Flattener(const PreprocessRun& run, const ResolveOptions& options, const GlslVersion& defaultVersion)
        : run_(run), options_(options), defaultVersion_(defaultVersion) {}

    void flatten() {
        body_.emplace_back(LineMarker{1, 0});
        walk(run_.files.front());
    }
    std::optional<GlslVersion> firstVersion() const {
        return version_ ? std::optional(version_->version) : std::nullopt;
    }
    void finish(ResolveResult& result) {
        const GlslVersion version = version_ ? version_->version : defaultVersion_;
        result.stage.versionDirective = version.directive();
        result.stage.versionNumber = version.number;
        result.stage.text = render(version);
        result.stage.variantPragmas = std::move(variantPragmas_);
        result.stage.targetsPragma = std::move(targetsPragma_);
        result.diagnostics.insert(result.diagnostics.end(), diagnostics_.begin(), diagnostics_.end());
    }

  private:
    void walk(const EnteredFile& file) {
        for (const LogicalLine& line : file.lines) {
            const auto directive = parseDirective(line);
            if (!directive) {
                emitCopy(line);
                continue;
            }
            const bool reached = file.reached.contains(line.firstLine);
            if (directive->name == "include") {
                if (auto child = file.includes.find(line.firstLine); child != file.includes.end()) {
                    // In place of the #include line, unless a comment ends or begins on it.
                    if (line.startsInComment) body_.push_back(blankedDirective(line).front());
                    body_.emplace_back(LineMarker{1, child->second});
                    walk(run_.files[child->second]);
                    const int next = line.firstLine + static_cast<int>(line.physical.size());
                    body_.emplace_back(LineMarker{line.endsInComment ? next - 1 : next, file.number});
                    if (line.endsInComment) body_.emplace_back(std::string("/*"));
                } else {
                    emitBlank(line);
                }
            } else if (directive->name == "version") {
                emitBlank(line);  // hoisted to line 1
                if (reached) handleVersion(file, line, *directive);
            } else if (isPrismPragma(*directive)) {
                emitBlank(line);
                if (reached) handlePragma(file, line, *directive);
            } else if (isPragmaOnce(*directive) || isIncludeExtension(*directive)) {
                emitBlank(line);
            } else if (auto rewritten = withIncludeMacrosDefined(line, *directive)) {
                body_.insert(body_.end(), rewritten->begin(), rewritten->end());
            } else {
                emitCopy(line);
            }
        }
    }

    Diagnostic& report(Severity severity, const EnteredFile& file, int line, int column, std::string message) {
        diagnostics_.push_back(makeDiagnostic(severity, file.display, line, column, std::move(message), file.chain));
        return diagnostics_.back();
    }

    void handleVersion(const EnteredFile& file, const LogicalLine& line, const Directive& directive) {
        const auto version = parseVersionArgument(directive.argument);
        if (!version) {
            report(Severity::Error, file, line.firstLine, directiveColumn(line),
                   "malformed #version: expected e.g. #version 330 core");
            return;
        }
        if (!version_) {
            version_ = SeenVersion{*version, file.display, line.firstLine};
            return;
        }
        if (version_->version.sameAs(*version)) return;
        auto& error = report(Severity::Error, file, line.firstLine, directiveColumn(line),
                             version->directive() + " conflicts with " + version_->version.directive() + " at " +
                                 placeName(version_->file, version_->line) +
                                 "; all files of a stage must ask for the same version");
        error.notes.push_back(makeNote(version_->file, version_->line, "first #version is here"));
    }

    void handlePragma(const EnteredFile& file, const LogicalLine& line, const Directive& directive) {
        const auto words = splitWhitespace(directive.argument);
        if (words.size() >= 2 && words[1] == "variant")
            return handleVariant(file, line, std::vector<std::string>(words.begin() + 2, words.end()));
        if (words.size() >= 2 && words[1] == "targets")
            return handleTargets(file, line, std::vector<std::string>(words.begin() + 2, words.end()));
        if (words.size() == 2 && words[1] == "reinclude") return;  // applied by the preprocessor
        report(Severity::Warning, file, line.firstLine, directiveColumn(line),
               "unknown #pragma prism '" + (words.size() >= 2 ? words[1] : std::string()) +
                   "' ignored (known: variant, targets, reinclude)");
    }

    // One declaration per stage: a second one that differs would leave the reader unsure
    // which wins, so it is an error naming the first.
    void handleTargets(const EnteredFile& file, const LogicalLine& line, const std::vector<std::string>& words) {
        TargetsPragma pragma{{}, file.display, line.firstLine};
        if (auto error = parseTargetList(joinWords(words), pragma.targets); !error.empty()) {
            report(Severity::Error, file, line.firstLine, directiveColumn(line), "#pragma prism targets: " + error);
            return;
        }
        if (!hasTarget(pragma.targets, Target::Gl)) {
            report(Severity::Error, file, line.firstLine, directiveColumn(line),
                   "#pragma prism targets " + targetListText(pragma.targets) +
                       ": list gl too; the desktop GLSL is the source every other target is made from and the "
                       "header embeds it for every shader");
            return;
        }
        if (!targetsPragma_) {
            targetsPragma_ = std::move(pragma);
            return;
        }
        if (targetsPragma_->targets == pragma.targets) return;
        auto& error =
            report(Severity::Error, file, line.firstLine, directiveColumn(line),
                   "#pragma prism targets " + targetListText(pragma.targets) + " conflicts with targets " +
                       targetListText(targetsPragma_->targets) + " at " +
                       placeName(targetsPragma_->file, targetsPragma_->line) + "; declare a stage's targets once");
        error.notes.push_back(makeNote(targetsPragma_->file, targetsPragma_->line, "targets first declared here"));
    }

    void handleVariant(const EnteredFile& file, const LogicalLine& line, const std::vector<std::string>& words) {
        if (auto message = checkVariantDeclaration(words); !message.empty()) {
            report(Severity::Error, file, line.firstLine, directiveColumn(line), std::move(message));
            return;
        }
        const std::vector<std::string> values(words.begin() + 1, words.end());
        const auto earlier = std::find_if(variantPragmas_.begin(), variantPragmas_.end(),
                                          [&](const VariantPragma& p) { return p.name == words[0]; });
        if (earlier == variantPragmas_.end()) {
            variantPragmas_.push_back({words[0], values, file.display, line.firstLine});
            return;
        }
        if (earlier->values == values) return;  // the same declaration in another module: merged
        auto& error = report(Severity::Error, file, line.firstLine, directiveColumn(line),
                             "variant " + words[0] + " declared with values {" + joinWords(values) + "} here but {" +
                                 joinWords(earlier->values) + "} at " + placeName(earlier->file, earlier->line));
        error.notes.push_back(makeNote(earlier->file, earlier->line, "variant " + words[0] + " first declared here"));
    }

    void emitCopy(const LogicalLine& line) { body_.insert(body_.end(), line.physical.begin(), line.physical.end()); }
    void emitBlank(const LogicalLine& line) {
        const auto lines = blankedDirective(line);
        body_.insert(body_.end(), lines.begin(), lines.end());
    }

    // Line 1 the version, then the -D defines, then the body; `#line` numbers follow
    // prism/catalog/line_directive.hpp (N or N + 1 by version).
    std::string render(const GlslVersion& version) const {
        const catalog::GlslVersionTag tag{version.number, version.isEs()};
        std::string text = version.directive() + "\n";
        for (const auto& [name, value] : options_.defines)
            text += "#define " + name + (value.empty() ? "" : " " + value) + "\n";
        for (const auto& piece : body_) {
            if (const auto* marker = std::get_if<LineMarker>(&piece)) {
                text += catalog::lineDirective(marker->nextLine, marker->source, tag) + "\n";
            } else {
                text += std::get<std::string>(piece) + "\n";
            }
        }
        return text;
    }

    const PreprocessRun& run_;
    const ResolveOptions& options_;
    GlslVersion defaultVersion_;
    std::optional<SeenVersion> version_;
    std::vector<OutputPiece> body_;
    std::vector<VariantPragma> variantPragmas_;
    std::optional<TargetsPragma> targetsPragma_;
    std::vector<Diagnostic> diagnostics_;
};

std::vector<Diagnostic> checkDefines(const ResolveOptions& options) {
    std::vector<Diagnostic> problems;
    for (const auto& [name, value] : options.defines)
        if (!isIdentifier(name) || value.find_first_of("\r\n") != std::string::npos)
            problems.push_back(makeError("", 0, 0, "invalid define '" + name + "=" + value + "'"));
    return problems;
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

    ModuleScanResult scan(const std::string& modulePath) {
        ModuleSource& module = result_.module;
        module.path = joinPath("", modulePath);
        const auto canonical = reader_.canonical(module.path);
        const auto text = canonical ? reader_.read(module.path) : std::nullopt;
        if (!text) {
            result_.diagnostics.push_back(
                makeError(module.path, 0, 0, canonical ? "cannot read the module" : "module not found"));
            return std::move(result_);
        }
        module.canonical = *canonical;
        const auto lines = splitLogicalLines(*text);
        const auto unconditional = unconditionalIncludes(lines);
        if (unconditional) {  // every #include is active: no condition to decide
            result_.diagnostics = checkConditionalStructure(module.path, lines);
            std::set<std::string> seen;
            for (const auto& target : *unconditional) {
                const auto dirs =
                    includeSearchDirs(target.second, {module.path}, options_.includeDirs, options_.baseDir);
                const auto found = findInclude(target.second, dirs, reader_);
                if (!found) {
                    result_.diagnostics.push_back(makeError(module.path, target.first.firstLine,
                                                            includeTargetColumn(target.first),
                                                            missingIncludeMessage(target.second, dirs)));
                } else if (seen.insert(found->canonical).second) {
                    module.includes.push_back(found->display);
                }
            }
        } else {  // which of them are active is glslang's to say
            const GlslVersion version =
                parseVersionDirective(options_.defaultVersion).value_or(GlslVersion{330, "core"});
            ResolveOptions alone = options_;
            alone.warnShadowedIncludes = false;  // a stage that includes the module says it, with its chain
            PreprocessRun run = preprocessWithGlslang(module.path, alone, version, reader_);
            result_.diagnostics = std::move(run.diagnostics);
            if (!run.files.empty())
                for (const auto& found : run.files.front().found) module.includes.push_back(found.display);
        }
        for (const auto& line : lines) {
            const auto directive = parseDirective(line);
            // #version stays: run-time composition checks it against the stage's, as resolution does.
            const bool blank = directive && (directive->name == "include" || isPragmaOnce(*directive) ||
                                             isIncludeExtension(*directive));
            for (const auto& physical : blank ? blankedDirective(line) : line.physical) module.text += physical + "\n";
        }
        module.description = leadingComment(lines);
        if (module.description.empty() && options_.warnUndocumentedModule)
            result_.diagnostics.push_back(makeDiagnostic(Severity::Warning, module.path, 1, 0,
                                                         "module has no leading comment saying what it provides"));
        result_.ok = !hasErrors(result_.diagnostics);
        return std::move(result_);
    }

  private:
    // The #include lines (with their targets) when none sits inside a conditional group
    // other than the file's own include guard, so all are active whatever the macros;
    // nullopt when some condition decides (or a line is malformed): then glslang runs.
    std::optional<std::vector<std::pair<LogicalLine, IncludeTarget>>> unconditionalIncludes(
        const std::vector<LogicalLine>& lines) const {
        const std::string guard = includeGuardOf(lines);
        for (const auto& define : options_.defines)
            if (define.first == guard) return std::nullopt;
        std::vector<std::pair<LogicalLine, IncludeTarget>> includes;
        int depth = 0;
        for (const auto& line : lines) {
            const auto directive = parseDirective(line);
            if (!directive) continue;
            const std::string& name = directive->name;
            if (name == "if" || name == "ifdef" || name == "ifndef") {
                ++depth;
            } else if (name == "endif") {
                --depth;
            } else if (name == "include") {
                const auto target = parseIncludeTarget(directive->argument);
                if (!target || depth > (guard.empty() ? 0 : 1)) return std::nullopt;
                includes.emplace_back(line, *target);
            } else if (name == "else" || name == "elif") {
                if (depth <= 1) return std::nullopt;  // a branch of the guard itself
            }
        }
        return includes;
    }

    const ResolveOptions& options_;
    const SourceReader& reader_;
    ModuleScanResult result_;
};

}  // namespace

ResolveResult resolveStage(const std::string& stagePath, const ResolveOptions& options, const SourceReader& reader) {
    ResolveResult result;
    result.diagnostics = checkDefines(options);
    const auto defaultVersion = parseVersionDirective(options.defaultVersion);
    if (!defaultVersion)
        result.diagnostics.push_back(
            makeError("", 0, 0, "invalid default version directive '" + options.defaultVersion + "'"));
    if (hasErrors(result.diagnostics)) return result;

    // glslang must know the version up front (its predefined macros depend on it); when
    // the first active #version is another one, run again with that one.
    GlslVersion assumed = leadingVersion(stagePath, reader).value_or(*defaultVersion);
    PreprocessRun run = preprocessWithGlslang(stagePath, options, assumed, reader);
    if (run.files.empty()) {
        result.diagnostics = std::move(run.diagnostics);
        return result;
    }
    auto flattener = std::make_unique<Flattener>(run, options, *defaultVersion);
    flattener->flatten();
    if (const auto found = flattener->firstVersion(); found && !found->sameAs(assumed) && run.ok) {
        assumed = *found;
        run = preprocessWithGlslang(stagePath, options, assumed, reader);
        flattener = std::make_unique<Flattener>(run, options, *defaultVersion);
        flattener->flatten();
    }
    result.diagnostics.insert(result.diagnostics.end(), run.diagnostics.begin(), run.diagnostics.end());
    flattener->finish(result);
    for (const auto& file : run.files) {
        result.stage.files.push_back({file.number, file.display, file.canonical, file.chain});
        result.stage.filesRead.push_back(file.display);
    }
    result.ok = run.ok && !hasErrors(result.diagnostics);
    return result;
}

ModuleScanResult scanModule(const std::string& modulePath, const ResolveOptions& options, const SourceReader& reader) {
    return ModuleScanner(options, reader).scan(modulePath);
}

}  // namespace prism::shaderc
