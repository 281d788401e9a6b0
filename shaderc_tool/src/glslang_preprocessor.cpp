// glslang's preprocessor as the judge of which lines are active (see
// glslang_preprocessor.hpp).
#include "glslang_preprocessor.hpp"

#include <memory>
#include <mutex>
#include <unordered_map>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <memory>
#include <regex>
#include <sstream>

#include "glslang_stage.hpp"
#include "preprocessor_limits.hpp"
#include "stage_files.hpp"
#include "shader_inputs.hpp"

namespace prism::shaderc {
namespace {

void initializeGlslangOnce() {
    static const bool initialized = [] { return glslang::InitializeProcess(); }();
    (void)initialized;
}

EShLanguage languageOf(const std::string& path) {
    const auto stage = stageOfPath(path);
    return stage ? glslangStage(*stage) : EShLangFragment;  // modules: as fragment code
}

EProfile profileOf(const GlslVersion& version) {
    const std::string profile = version.effectiveProfile();
    if (profile == "es") return EEsProfile;
    if (profile == "compatibility") return ECompatibilityProfile;
    if (profile == "core") return ECoreProfile;
    return ENoProfile;
}

bool isProbed(const Directive& d) {
    return d.name == "version" || isPragmaOnce(d) || isPrismPragma(d);
}

// The text glslang reads for `lines`: the same lines, with #include targets prefixed
// by their line ("L:") and the probed directives turned into `#include "L?"`.
std::string textForGlslang(const std::vector<LogicalLine>& lines) {
    std::string out;
    for (const auto& line : lines) {
        const auto directive = parseDirective(line);
        std::string replacement;
        if (directive && directive->name == "include") {
            const auto target = parseIncludeTarget(directive->argument);
            const std::string tag = std::to_string(line.firstLine);
            replacement = !target          ? "#include \"" + tag + "?\""
                          : target->angled ? "#include <" + tag + ":" + target->name + ">"
                                           : "#include \"" + tag + ":" + target->name + "\"";
        } else if (directive && isProbed(*directive)) {
            replacement = "#include \"" + std::to_string(line.firstLine) + "?\"";
        }
        if (replacement.empty()) {
            for (const auto& physical : line.physical) out += physical + "\n";
            continue;
        }
        const std::size_t hash = line.code.find('#');
        const std::string& first = line.physical.front();
        out += (hash < first.size() ? first.substr(0, hash) : std::string()) + replacement;
        for (std::size_t i = 1; i < line.physical.size(); ++i) out += "\n";
        out += line.endsInComment ? " /*\n" : "\n";  // the comment goes on below
    }
    return out;
}

// What a file's text alone decides (its logical lines, include guard, the text glslang
// reads, whether its conditionals balance), computed once per distinct text: the same
// modules enter every variant of every stage.
struct FileAnalysis {
    std::vector<LogicalLine> lines;
    std::string guard;
    std::string glslangText;
    bool balanced = true;
};

std::shared_ptr<const FileAnalysis> analysisOf(const std::string& text) {
    static std::mutex mutex;
    static std::unordered_map<std::string, std::shared_ptr<const FileAnalysis>> known;
    {
        std::lock_guard lock(mutex);
        if (auto it = known.find(text); it != known.end()) return it->second;
    }
    auto analysis = std::make_shared<FileAnalysis>();
    analysis->lines = splitLogicalLines(text);
    analysis->balanced = checkConditionalStructure("", analysis->lines).empty();
    analysis->guard = includeGuardOf(analysis->lines);
    analysis->glslangText = textForGlslang(analysis->lines);
    std::lock_guard lock(mutex);
    // Bounded: the runtime's hot reload runs these stages in a long-lived process.
    if (known.size() >= 4096) known.clear();
    return known.try_emplace(text, std::move(analysis)).first->second;
}

std::string describeChain(const std::vector<std::string>& files) {
    std::string text;
    const std::size_t n = files.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (n > 12 && i == 5) {
            text += " -> ... (" + std::to_string(n - 10) + " more)";
            i = n - 6;
            continue;
        }
        text += (i ? " -> " : "") + files[i];
    }
    return text;
}

class RecordingIncluder final : public glslang::TShader::Includer {
  public:
    RecordingIncluder(const ResolveOptions& options, const SourceReader& reader, PreprocessRun& run)
        : options_(options), reader_(reader), run_(run) {
        for (const auto& [name, value] : options.defines) macroSizes_.define(name, value);
    }

    // Reads the top file; its glslang text (which glslang must read in place: a line over
    // a limit found later is blanked there), or null after reporting why not.
    const std::string* enterTop(const std::string& path) {
        const std::string display = joinPath("", path);
        const auto canonical = reader_.canonical(display);
        const auto text = canonical ? reader_.read(display) : std::nullopt;
        if (!text) {
            run_.diagnostics.push_back(makeError(display, 0, 0, canonical ? "cannot read the file" : "file not found"));
            return nullptr;
        }
        EnteredFile& top = enter(display, *canonical, {}, *text);
        if (hasLimitErrors_) return nullptr;
        return &texts_[top.number];
    }

    IncludeResult* includeLocal(const char* name, const char* includer, size_t depth) override {
        return handle(name, includer, depth);
    }
    IncludeResult* includeSystem(const char* name, const char* includer, size_t depth) override {
        return handle(name, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override { delete result; }

    const std::string* fileKey(const std::string& key, int& number) const {
        number = -1;
        if (key.empty() || !std::all_of(key.begin(), key.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return nullptr;
        number = std::stoi(key);
        return number < static_cast<int>(run_.files.size()) ? &run_.files[number].display : nullptr;
    }

  private:
    struct FileFlags {
        bool once = false;       // an active #pragma once
        bool reinclude = false;  // an active #pragma prism reinclude
        std::string guard;
        bool entered = false;
    };

    IncludeResult* nothing() { return new IncludeResult("-", nullptr, 0, nullptr); }

    EnteredFile& enter(const std::string& display, const std::string& canonical, std::vector<IncludeSite> chain,
                       const std::string& text) {
        EnteredFile file;
        file.number = static_cast<std::uint32_t>(run_.files.size());
        file.display = display;
        file.canonical = canonical;
        file.chain = std::move(chain);
        const auto analysis = analysisOf(text);
        file.lines = analysis->lines;
        auto limitErrors =
            analysis->balanced ? std::vector<Diagnostic>{} : checkConditionalStructure(display, file.lines);
        for (auto& e : checkPreprocessorLimits(display, file.lines, macroSizes_)) limitErrors.push_back(std::move(e));
        for (auto& e : limitErrors) {
            e.includedFrom = file.chain;
            hasLimitErrors_ = true;
            run_.diagnostics.push_back(std::move(e));
        }
        FileFlags& flags = flags_[canonical];
        if (!flags.entered) flags.guard = analysis->guard;
        flags.entered = true;
        texts_.push_back(limitErrors.empty() ? analysis->glslangText : std::string());
        stack_.push_back(file.number);
        run_.files.push_back(std::move(file));
        return run_.files.back();
    }

    Diagnostic& report(const EnteredFile& file, int line, int column, std::string message) {
        Diagnostic d = makeError(file.display, line, column, std::move(message));
        d.includedFrom = file.chain;
        run_.diagnostics.push_back(std::move(d));
        return run_.diagnostics.back();
    }

    const LogicalLine* lineAt(const EnteredFile& file, int firstLine) const {
        const auto at = std::lower_bound(file.lines.begin(), file.lines.end(), firstLine,
                                         [](const LogicalLine& line, int n) { return line.firstLine < n; });
        return at != file.lines.end() && at->firstLine == firstLine ? &*at : nullptr;
    }

    IncludeResult* handle(const std::string& request, const std::string& includerKey, std::size_t depth) {
        if (request.starts_with("!cycle:")) {  // a guard probe found the guard undefined
            run_.diagnostics.push_back(pendingCycles_.at(std::stoul(request.substr(7))));
            return nothing();
        }
        int number = -1;
        if (!fileKey(includerKey, number)) return nothing();
        // glslang's include stack: the top file, then `depth - 1` open includes.
        if (stack_.size() > depth) stack_.resize(depth);
        EnteredFile& includer = run_.files[static_cast<std::size_t>(number)];
        // Our own rewriting: "<line>:<target>" or "<line>?"; anything else is a directive
        // glslang saw where prism-shaderc saw none.
        std::size_t separator = 0;
        while (separator < request.size() && separator < 9 && request[separator] >= '0' && request[separator] <= '9')
            ++separator;
        if (separator == 0 || separator >= request.size() || (request[separator] != ':' && request[separator] != '?')) {
            report(includer, 0, 0,
                   "glslang found an #include of \"" + request +
                       "\" that prism-shaderc did not recognise as a directive; write it on its own line");
            return nothing();
        }
        const int line = std::stoi(request.substr(0, separator));
        includer.reached.insert(line);
        const LogicalLine* logical = lineAt(includer, line);
        if (!logical) return nothing();
        if (request[separator] == '?') return probe(includer, *logical);
        const auto target = parseIncludeTarget(parseDirective(*logical)->argument);
        return include(number, *logical, *target, depth);
    }

    IncludeResult* probe(EnteredFile& file, const LogicalLine& line) {
        const auto directive = parseDirective(line);
        if (directive->name == "include") {
            report(file, line.firstLine, directiveColumn(line),
                   "malformed #include: expected #include \"file\" or #include <file>");
        } else if (isPragmaOnce(*directive)) {
            flags_[file.canonical].once = true;
        } else if (isPrismPragma(*directive)) {
            const auto words = splitWhitespace(directive->argument);
            if (words.size() == 2 && words[1] == "reinclude") flags_[file.canonical].reinclude = true;
        }
        return nothing();
    }

    std::vector<std::string> chainNames(std::size_t upTo) const {
        std::vector<std::string> names;
        for (std::size_t i = 0; i < upTo && i < stack_.size(); ++i) names.push_back(run_.files[stack_[i]].display);
        return names;
    }

    // `found` is open already, at `openAt` in the stack: unless #pragma once skips it, an
    // include cycle. With an include guard, whether the guard is defined is glslang's to
    // say: a probe asks it, and the error is reported only when the probe is entered.
    IncludeResult* cycle(const EnteredFile& includer, int lineNumber, int column, const FoundFile& found,
                         std::size_t openAt) {
        const FileFlags& flags = flags_[found.canonical];
        if (flags.once) return nothing();
        auto names = chainNames(stack_.size());
        names.erase(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(openAt));
        names.push_back(found.display);
        Diagnostic error = makeError(
            includer.display, lineNumber, column,
            "include cycle: " + describeChain(names) + "; add an include guard or #pragma once, or break the cycle");
        error.includedFrom = includer.chain;
        if (flags.guard.empty()) {
            run_.diagnostics.push_back(std::move(error));
            return nothing();
        }
        pendingCycles_.push_back(std::move(error));
        const std::string probeName = "!cycle:" + std::to_string(pendingCycles_.size() - 1);
        probes_.push_back("#ifndef " + flags.guard + "\n#include \"" + probeName + "\"\n#endif\n");
        return new IncludeResult("guard", probes_.back().data(), probes_.back().size(), nullptr);
    }
    IncludeResult* include(int includerNumber, const LogicalLine& line, const IncludeTarget& target,
                           std::size_t depth) {
        EnteredFile& includer = run_.files[static_cast<std::size_t>(includerNumber)];
        std::vector<std::string> chain;  // innermost first
        for (auto it = stack_.rbegin(); it != stack_.rend(); ++it) chain.push_back(run_.files[*it].display);
        const auto dirs = includeSearchDirs(target, chain, options_.includeDirs, options_.baseDir);
        const auto found = findInclude(target, dirs, reader_);
        const int column = includeTargetColumn(line);
        if (!found) {
            report(includer, line.firstLine, column, missingIncludeMessage(target, dirs));
            return nothing();
        }
        if (std::none_of(includer.found.begin(), includer.found.end(),
                         [&](const FoundFile& f) { return f.canonical == found->canonical; }))
            includer.found.push_back(*found);
        if (options_.warnShadowedIncludes)
            if (auto message = shadowedIncludeMessage(target, dirs, *found, reader_); !message.empty())
                report(includer, line.firstLine, column, std::move(message)).severity = Severity::Warning;

        FileFlags& flags = flags_[found->canonical];
        const auto open = std::find_if(stack_.begin(), stack_.end(),
                                       [&](std::uint32_t n) { return run_.files[n].canonical == found->canonical; });
        if (open != stack_.end() && !flags.reinclude)
            return cycle(includer, line.firstLine, column, *found, static_cast<std::size_t>(open - stack_.begin()));
        if (flags.entered && !flags.reinclude) return nothing();  // include-once
        if (depth > static_cast<std::size_t>(kMaxIncludeDepth)) {
            auto names = chainNames(stack_.size());
            names.push_back(found->display);
            report(includer, line.firstLine, column,
                   "includes nested more than " + std::to_string(kMaxIncludeDepth) +
                       " files deep (limit): " + describeChain(names));
            return nothing();
        }
        const auto text = reader_.read(found->display);
        if (!text) {
            report(includer, line.firstLine, column, "cannot read include file " + found->display);
            return nothing();
        }
        std::vector<IncludeSite> sites{{includer.display, line.firstLine}};
        sites.insert(sites.end(), includer.chain.begin(), includer.chain.end());
        hasLimitErrors_ = false;
        openIncludeLine_[static_cast<std::uint32_t>(includerNumber)] = line.firstLine;
        const std::size_t definitionsBefore = macroSizes_.definitionCount();
        const std::uint32_t child = enter(found->display, found->canonical, std::move(sites), *text).number;
        // `enter` grew run_.files: `includer` may dangle from here on.
        run_.files[static_cast<std::size_t>(includerNumber)].includes[line.firstLine] = child;
        if (macroSizes_.definitionCount() != definitionsBefore) recheckOpenFiles();
        const std::string& childText = texts_[child];
        if (childText.empty()) return nothing();
        return new IncludeResult(std::to_string(child), childText.data(), childText.size(), nullptr);
    }

    // The lines of the open files below their open #include were checked before the file
    // it names defined its macros: check them again with those (`M` defined in an include
    // and used after it). A line over a limit is reported and blanked in glslang's text
    // before glslang reads it.
    void recheckOpenFiles() {
        for (std::size_t i = 0; i + 1 < stack_.size(); ++i) {  // the last one is the file just entered
            const std::uint32_t number = stack_[i];
            const EnteredFile& file = run_.files[number];
            const int after = openIncludeLine_[number];
            const auto rest = std::upper_bound(file.lines.begin(), file.lines.end(), after,
                                               [](int n, const LogicalLine& line) { return n < line.firstLine; });
            MacroSizeTable macros = macroSizes_;  // the rest's own #defines are counted again, in order
            for (auto& e : checkPreprocessorLimits(file.display, std::span(rest, file.lines.end()), macros)) {
                if (!limitLinesReported_.insert({number, e.line}).second) continue;
                blankLine(texts_[number], e.line, lineAt(file, e.line)->physical.size());
                e.includedFrom = file.chain;
                run_.diagnostics.push_back(std::move(e));
            }
        }
    }

    // Spaces over the physical lines [first, first + count) of `text`, newlines kept.
    static void blankLine(std::string& text, int first, std::size_t count) {
        std::size_t at = 0;
        for (int line = 1; line < first; ++line) {
            const auto end = text.find('\n', at);
            if (end == std::string::npos) return;
            at = end + 1;
        }
        for (std::size_t seen = 0; at < text.size() && seen < count; ++at) {
            if (text[at] == '\n')
                ++seen;
            else
                text[at] = ' ';
        }
    }

    const ResolveOptions& options_;
    const SourceReader& reader_;
    PreprocessRun& run_;
    MacroSizeTable macroSizes_;
    std::map<std::uint32_t, int> openIncludeLine_;  // file -> line of its #include now open
    std::set<std::pair<std::uint32_t, int>> limitLinesReported_;
    std::deque<std::string> texts_;   // glslang's text of each entered file (stable addresses)
    std::deque<std::string> probes_;  // guard probes
    std::vector<Diagnostic> pendingCycles_;
    std::map<std::string, FileFlags> flags_;  // by canonical path
    std::vector<std::uint32_t> stack_;        // open files, top file first
    bool hasLimitErrors_ = false;
};

// "ERROR: 3:12: '#error' : text" -> an error at file 3, line 12.
void addGlslangErrors(const std::string& log, const RecordingIncluder& includer, PreprocessRun& run) {
    static const std::regex located(R"(^ERROR: ([^:]*):(\d+): (.*)$)");
    static const std::regex token(R"(^'([^']*)' : (.*)$)");
    std::istringstream in(log);
    std::string text;
    while (std::getline(in, text)) {
        std::smatch m;
        if (!std::regex_match(text, m, located)) continue;
        std::string message = m[3];
        while (!message.empty() && message.back() == ' ') message.pop_back();
        // Every file's conditionals balance (checked before), so this only follows
        // another error.
        if (message.ends_with("missing #endif")) continue;
        std::smatch t;
        if (std::regex_match(message, t, token))
            message = t[1].length() ? "'" + t[1].str() + "': " + t[2].str() : t[2].str();
        int number = -1;
        const bool known = includer.fileKey(m[1], number) != nullptr;
        const EnteredFile& file = run.files[known ? static_cast<std::size_t>(number) : 0];
        Diagnostic d = makeError(file.display, std::stoi(m[2]), 0, std::move(message));
        d.includedFrom = file.chain;
        run.diagnostics.push_back(std::move(d));
    }
}

}  // namespace

// The guard macro G of a file shaped `#ifndef G` / `#define G` ... `#endif` (or
// `#if !defined(G)`), with only blank lines and comments outside; "" when none.
std::string includeGuardOf(const std::vector<LogicalLine>& lines) {
    std::vector<std::pair<const LogicalLine*, Directive>> directives;
    for (const auto& line : lines) {
        if (auto d = parseDirective(line)) {
            directives.emplace_back(&line, std::move(*d));
        } else if (!trim(line.code).empty()) {
            if (directives.empty()) return {};  // code before the guard
            directives.emplace_back(&line, Directive{"<code>", ""});
        }
    }
    if (directives.size() < 3) return {};
    std::string guard;
    const Directive& first = directives[0].second;
    if (first.name == "ifndef") {
        guard = std::string(trim(first.argument));
    } else if (first.name == "if") {
        static const std::regex notDefined(R"(^!\s*defined\s*(?:\(\s*(\w+)\s*\)|(\w+))$)");
        std::smatch m;
        const std::string argument(trim(first.argument));
        if (std::regex_match(argument, m, notDefined)) guard = m[1].matched ? m[1].str() : m[2].str();
    }
    if (!isIdentifier(guard)) return {};
    const auto defineWords = splitWhitespace(directives[1].second.argument);
    if (directives[1].second.name != "define" || defineWords.empty() || defineWords[0] != guard) return {};
    int depth = 0;
    for (std::size_t i = 0; i < directives.size(); ++i) {
        const std::string& name = directives[i].second.name;
        if (name == "if" || name == "ifdef" || name == "ifndef") ++depth;
        if (name == "endif" && --depth == 0) return i + 1 == directives.size() ? guard : std::string();
        if (depth == 0) return {};  // something outside the guarded group
    }
    return {};
}

double buildGlslangBuiltIns(const GlslVersion& version) {
    const auto start = std::chrono::steady_clock::now();
    initializeGlslangOnce();
    glslang::TShader shader(EShLangVertex);
    const char* empty = "";
    shader.setStrings(&empty, 1);
    std::string output;
    glslang::TShader::ForbidIncluder includer;
    shader.preprocess(GetDefaultResources(), version.number, profileOf(version), true, false, EShMsgDefault, &output,
                      includer);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

PreprocessRun preprocessWithGlslang(const std::string& path, const ResolveOptions& options, const GlslVersion& version,
                                    const SourceReader& reader) {
    initializeGlslangOnce();
    PreprocessRun run;
    RecordingIncluder includer(options, reader, run);
    const std::string* text = includer.enterTop(path);
    if (!text) return run;

    std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
    for (const auto& [name, value] : options.defines) preamble += "#define " + name + " " + value + "\n";
    glslang::TShader shader(languageOf(path));
    const char* strings[] = {text->c_str()};
    const char* names[] = {"0"};
    shader.setStringsWithLengthsAndNames(strings, nullptr, names, 1);
    shader.setPreamble(preamble.c_str());
    options.rules.configure(shader, languageOf(path));
    std::string output;
    const bool ok = shader.preprocess(GetDefaultResources(), version.number, profileOf(version), true, false,
                                      options.rules.messages(), &output, includer);
    if (!ok) addGlslangErrors(shader.getInfoLog(), includer, run);
    run.ok = std::none_of(run.diagnostics.begin(), run.diagnostics.end(),
                          [](const Diagnostic& d) { return d.severity == Severity::Error; });
    return run;
}

}  // namespace prism::shaderc
