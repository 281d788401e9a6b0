// glslang compilation, linking and message mapping for one program variant.
#include "validator.hpp"

#include <prism/catalog/line_directive.hpp>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Include/PoolAlloc.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <regex>
#include <sstream>
#include <tuple>

#include "did_you_mean.hpp"
#include "glslang_stage.hpp"
#include "directive_lines.hpp"
#include "assigned_locations.hpp"
#include "contract_check.hpp"
#include "interface_check.hpp"
#include "spirv_source_lines.hpp"
#include "stage_interface.hpp"
#include "vulkan_reflection.hpp"
#include "vulkan_stage_rules.hpp"

namespace prism::shaderc {
namespace {

EShMessages messagesFor(const StageToValidate& s) {
    return s.rules.messages();
}

// glslang's refusal of Vulkan GLSL under the OpenGL client, as one error that names the
// construct and the option that accepts it; "" for any other message.
std::string vulkanOnlyHint(const std::string& token, const std::string& message) {
    const bool vulkanOnly = message.find("only allowed when using GLSL for Vulkan") != std::string::npos ||
                            message.find("only allowed when generating SPIR-V") != std::string::npos;
    const bool vulkanBuiltIn = (token == "gl_VertexIndex" || token == "gl_InstanceIndex") &&
                               message.find("undeclared identifier") != std::string::npos;
    if (!vulkanOnly && !vulkanBuiltIn) return {};
    return "'" + token +
           "' is Vulkan GLSL, and this stage is validated as OpenGL GLSL; build it with --client vulkan "
           "(prism_add_shaders(... CLIENT vulkan)), or use the OpenGL equivalent" +
           (token == "gl_VertexIndex"     ? " gl_VertexID"
            : token == "gl_InstanceIndex" ? " gl_InstanceID"
                                          : "");
}

EProfile profileOf(const std::string& versionDirective) {
    if (versionDirective.find(" es") != std::string::npos) return EEsProfile;
    if (versionDirective.find("compatibility") != std::string::npos) return ECompatibilityProfile;
    if (versionDirective.find("core") != std::string::npos) return ECoreProfile;
    return ENoProfile;
}

// A compute stage below its profile's first version with compute shaders (GLSL 4.30,
// GLSL ES 3.10, as glslang and glslc require): the message, naming the profile; "" otherwise.
std::string computeVersionError(const StageToValidate& s) {
    if (s.stage != catalog::Stage::Compute) return {};
    const int version = s.resolved.versionNumber;
    if (profileOf(s.resolved.versionDirective) == EEsProfile)
        return version >= 310 ? std::string()
                              : "compute shaders need GLSL ES 310 or newer, this stage is " + std::to_string(version) +
                                    " es; add `#version 310 es`";
    return version >= 430 ? std::string()
                          : "compute shaders need GLSL 430 or newer, this stage is " + std::to_string(version) +
                                "; add `#version 430 core` or pass --glsl-version 430";
}

// The text of every (source number, line) in a flattened stage, recovered from its
// `#line N S` directives, so a message's token can be given a column.
class SourceLines {
  public:
    SourceLines(const ResolvedStage& stage) {
        std::istringstream in(stage.text);
        std::string line;
        std::uint32_t source = 0;
        int next = 1;
        const auto version = catalog::glslVersionOf(stage.versionDirective);
        bool first = true;
        while (std::getline(in, line)) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            unsigned n = 0, s = 0;
            if (std::sscanf(line.c_str(), " #line %u %u", &n, &s) == 2) {
                next = catalog::lineAfterDirective(static_cast<int>(n), version);
                source = s;
                first = false;
                continue;
            }
            if (!first) lines_[{source, next}] = line;
            ++next;
        }
    }
    const std::string* find(std::uint32_t source, int line) const {
        auto it = lines_.find({source, line});
        return it == lines_.end() ? nullptr : &it->second;
    }

    // glslang's linker objects carry no source location, so a global's declaration is
    // found in the text: the first line declaring `name` with a storage qualifier.
    void locateDeclaration(InterfaceVariable& v) const {
        if (v.line > 0) return;
        static const std::vector<std::string_view> storage = {"in",
                                                              "out",
                                                              "uniform",
                                                              "buffer",
                                                              "rayPayloadEXT",
                                                              "rayPayloadInEXT",
                                                              "hitAttributeEXT",
                                                              "callableDataEXT",
                                                              "callableDataInEXT",
                                                              "rayPayloadNV",
                                                              "rayPayloadInNV",
                                                              "hitAttributeNV",
                                                              "callableDataNV",
                                                              "callableDataInNV"};
        if (const auto found = declarationOf(v.name, storage)) std::tie(v.sourceNumber, v.line, v.column) = *found;
    }

    // The first line that declares `name` (a word of it) with one of `qualifiers`, as
    // (source number, line, column); without `qualifiers`, the first line naming it.
    std::optional<std::tuple<std::uint32_t, int, int>> declarationOf(
        const std::string& name, const std::vector<std::string_view>& qualifiers) const {
        for (const auto& [key, text] : lines_) {
            const std::string_view code = std::string_view(text).substr(0, text.find("//"));
            const auto column = findWord(code, name);
            if (column == std::string_view::npos) continue;
            const bool qualified = qualifiers.empty() || std::any_of(qualifiers.begin(), qualifiers.end(), [&](auto q) {
                                       return findWord(code, q) != std::string_view::npos;
                                   });
            if (qualified) return std::tuple{key.first, key.second, static_cast<int>(column) + 1};
        }
        return std::nullopt;
    }

  private:
    std::map<std::pair<std::uint32_t, int>, std::string> lines_;
};

// The column glslang's message points at: the token it names on that line, else
// (glslang gives no column, e.g. for a syntax error) the line's first non-blank one.
int columnOf(const std::string* lineText, const std::string& tok) {
    if (!lineText) return 0;
    if (!tok.empty())
        if (const auto pos = findWord(*lineText, tok); pos != std::string_view::npos) return static_cast<int>(pos) + 1;
    if (!tok.empty())
        if (const auto pos = lineText->find(tok); pos != std::string::npos) return static_cast<int>(pos) + 1;
    const auto first = lineText->find_first_not_of(" \t");
    return first == std::string::npos ? 0 : static_cast<int>(first) + 1;
}

struct StageMaps {
    const StageToValidate* stage;
    SourceLines lines;
};

std::string pathOf(const StageToValidate& s, std::uint32_t number) {
    if (number < s.resolved.files.size()) return s.resolved.files[number].path;
    return s.path;
}

std::vector<IncludeSite> chainOf(const StageToValidate& s, std::uint32_t number) {
    if (number < s.resolved.files.size()) return s.resolved.files[number].chain;
    return {};
}

// Turns glslang's info log ("ERROR: 2:15: 'u_colr' : undeclared identifier") into
// diagnostics at the module's own file:line:col. Later errors on a line that already
// has one are glslang's follow-ons: they are counted into a note, not printed.
std::vector<Diagnostic> mapInfoLog(const std::string& log, const StageMaps& maps) {
    static const std::regex located(R"(^(ERROR|WARNING): (\d+):(\d+): (.*)$)");
    static const std::regex token(R"(^'([^']*)' : (.*)$)");
    std::vector<Diagnostic> out;
    std::map<std::pair<std::uint32_t, int>, std::size_t> firstOnLine;
    std::map<std::size_t, int> followOns;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (!std::regex_match(line, m, located)) {
            if (line.rfind("ERROR: ", 0) == 0 && line.find("compilation errors") == std::string::npos &&
                line.find("No code generated") == std::string::npos)
                out.push_back(makeError(maps.stage->path, 0, 0, line.substr(7)));
            continue;
        }
        auto source = static_cast<std::uint32_t>(std::stoul(m[2]));
        int lineNo = std::stoi(m[3]);
        std::string message = m[4];
        while (!message.empty() && message.back() == ' ') message.pop_back();
        if (message.find("compilation terminated") != std::string::npos) continue;
        int column = 0;
        std::string tok;
        std::smatch t;
        if (std::regex_match(message, t, token)) {
            tok = t[1];
            std::string rest = t[2];
            rest.erase(0, rest.find_first_not_of(' '));  // glslang writes "'' :  syntax error"
            message = tok.empty() ? rest : "'" + tok + "': " + rest;
            if (maps.stage->rules.explainsVulkanGlsl)
                if (auto hint = vulkanOnlyHint(tok, rest); !hint.empty()) message = std::move(hint);
        }
        column = columnOf(maps.lines.find(source, lineNo), tok);
        if (!tok.empty() && message.ends_with("no matching overloaded function found")) {
            auto functions = functionNamesIn(maps.stage->resolved.text);
            if (!std::binary_search(functions.begin(), functions.end(), tok)) message += didYouMean(tok, functions);
        }
        Diagnostic d = makeError(pathOf(*maps.stage, source), lineNo, column, message);
        d.severity = m[1] == "ERROR" ? Severity::Error : Severity::Warning;
        d.includedFrom = chainOf(*maps.stage, source);
        if (d.severity == Severity::Error) {
            auto [it, fresh] = firstOnLine.try_emplace({source, lineNo}, out.size());
            if (!fresh) {
                ++followOns[it->second];
                continue;
            }
        }
        out.push_back(std::move(d));
    }
    for (auto [index, count] : followOns) {
        auto& d = out[index];
        d.notes.push_back(
            {Severity::Note,
             d.file,
             d.line,
             d.column,
             std::to_string(count) + " follow-on error" + (count > 1 ? "s" : "") + " on the same line suppressed",
             {},
             {}});
    }
    return out;
}

}  // namespace

void initializeValidator() {
    glslang::InitializeProcess();
}
void finalizeValidator() {
    glslang::FinalizeProcess();
}

struct CompiledStage {
    std::unique_ptr<glslang::TShader> shader;  // null when the stage could not be compiled
    bool ok = false;
    std::vector<Diagnostic> diagnostics;
    std::mutex mutex;  // held while a program links or reads the shader
};

std::shared_ptr<CompiledStage> compileStage(const StageToValidate& s) {
    auto compiled = std::make_shared<CompiledStage>();
    if (auto tooOld = computeVersionError(s); !tooOld.empty()) {
        compiled->diagnostics.push_back(makeError(s.path, 1, 1, tooOld));
        return compiled;
    }
    auto shader = std::make_unique<glslang::TShader>(glslangStage(s.stage));
    const char* text = s.resolved.text.c_str();
    shader->setStrings(&text, 1);
    s.rules.configure(*shader, glslangStage(s.stage));
    compiled->ok = shader->parse(GetDefaultResources(), s.resolved.versionNumber,
                                 profileOf(s.resolved.versionDirective), false, false, messagesFor(s));
    if (const char* log = shader->getInfoLog(); log && *log) {  // the line texts only when there is a message
        const StageMaps maps{&s, SourceLines(s.resolved)};
        compiled->diagnostics = mapInfoLog(log, maps);
    }
    if (!compiled->ok) {
        bool hasError = false;
        for (const auto& d : compiled->diagnostics) hasError = hasError || d.severity == Severity::Error;
        if (!hasError) compiled->diagnostics.push_back(makeError(s.path, 0, 0, "glslang rejected this stage"));
    }
    compiled->shader = std::move(shader);
    return compiled;
}

bool compiledCleanly(const CompiledStage& stage) {
    return stage.ok && stage.diagnostics.empty();
}

ValidatedVariant validateProgram(const std::vector<StageToValidate>& stages, const Contract& contract,
                                 const LinkedProgramCheck& check) {
    std::vector<std::shared_ptr<CompiledStage>> compiled;
    for (const auto& s : stages) compiled.push_back(compileStage(s));
    return validateCompiledProgram(stages, compiled, contract, check);
}

namespace {

SourceLocator locatorFor(const std::vector<StageToValidate>& stages) {
    SourceLocator locate;
    locate.path = [&stages](std::size_t stage, std::uint32_t number) { return pathOf(stages[stage], number); };
    locate.chain = [&stages](std::size_t stage, std::uint32_t number) { return chainOf(stages[stage], number); };
    return locate;
}

std::vector<StageInterface> interfacesOf(const std::vector<StageToValidate>& stages,
                                         const std::vector<glslang::TShader*>& shaders) {
    std::vector<StageInterface> interfaces;
    for (std::size_t i = 0; i < stages.size(); ++i)
        interfaces.push_back(extractStageInterface(stages[i].stage, *shaders[i]));
    return interfaces;
}

// glslang's locations of the linker objects are rough: a message finds its declaration's line.
void locateDeclarations(const std::vector<StageToValidate>& stages, std::vector<StageInterface>& interfaces) {
    for (std::size_t i = 0; i < stages.size(); ++i) {
        const SourceLines lines(stages[i].resolved);
        for (auto& v : interfaces[i].variables) lines.locateDeclaration(v);
    }
}

// Where the stages meet, as their client makes them meet: the stage interfaces (not in a
// ray-tracing program, which has none); under Vulkan the descriptors by set and binding and
// the ray-tracing data, under OpenGL the binding contract (what the runtime feeds by name).
std::vector<Diagnostic> crossStageMessages(const std::vector<StageToValidate>& stages,
                                           const std::vector<StageInterface>& interfaces, const Contract& contract) {
    const SourceLocator locate = locatorFor(stages);
    std::vector<Diagnostic> out;
    const auto add = [&out](std::vector<Diagnostic> more) { out.insert(out.end(), more.begin(), more.end()); };
    if (!isRayTracingStage(stages.front().stage)) add(checkStageInterfaces(interfaces, locate));
    if (stages.front().rules.linksStageByStage) {
        add(checkDescriptorBindings(interfaces, locate));
        add(checkRayTracingData(interfaces, locate));
    } else if (stages.front().rules.checksContract) {
        add(checkContract(contract, interfaces, locate));
    }
    return out;
}

// The cross-stage checks; messages find the declarations' lines.
std::vector<Diagnostic> checkInterfaces(const std::vector<StageToValidate>& stages,
                                        const std::vector<glslang::TShader*>& shaders, const Contract& contract) {
    auto interfaces = interfacesOf(stages, shaders);
    auto found = crossStageMessages(stages, interfaces, contract);
    if (found.empty()) return found;
    locateDeclarations(stages, interfaces);  // messages: find the declarations' lines, then check again
    return crossStageMessages(stages, interfaces, contract);
}

// The relaxed rules' mapIO, then its locations checked against the stages as written
// (assigned_locations.hpp). False with the messages in `result` when it failed.
bool assignLocations(const std::vector<StageToValidate>& stages, const std::vector<glslang::TShader*>& shaders,
                     glslang::TProgram& program, ValidatedVariant& result) {
    const auto written = interfacesOf(stages, shaders);
    if (!program.mapIO()) {
        result.diagnostics.push_back(
            makeError(stages.front().path, 0, 0, "glslang could not assign locations and bindings"));
        return false;
    }
    // Without an explicit location on an input or output there is nothing to collide with.
    const auto explicitLocation = [](const StageInterface& stage) {
        return std::any_of(stage.variables.begin(), stage.variables.end(), [](const InterfaceVariable& v) {
            return v.location >= 0 && (v.storage == StorageKind::In || v.storage == StorageKind::Out);
        });
    };
    if (std::none_of(written.begin(), written.end(), explicitLocation)) return true;
    auto assigned = interfacesOf(stages, shaders);
    if (checkAssignedLocations(written, assigned, locatorFor(stages)).empty()) return true;
    locateDeclarations(stages, assigned);
    const auto overlaps = checkAssignedLocations(written, assigned, locatorFor(stages));
    result.diagnostics.insert(result.diagnostics.end(), overlaps.begin(), overlaps.end());
    return false;
}

// A validator message moved to the declaration its instruction names (a block's type, a
// variable), found in the stage's text: first one declared with a storage or struct
// keyword, else any line naming it.
SpirvSiteLocator declarationLocator(const StageToValidate& s) {
    return [&s](const SpirvSite& site, Diagnostic& d) {
        if (site.inFunction) return false;  // a statement's: its line comes from the words' line info
        static const std::vector<std::string_view> declaring = {"uniform", "buffer", "struct", "shared",
                                                                "in",      "out",    "const"};
        const SourceLines lines(s.resolved);
        for (const auto& qualifiers : {declaring, std::vector<std::string_view>{}})
            for (const auto& name : site.names)
                if (const auto found = lines.declarationOf(name, qualifiers)) {
                    const auto [source, line, column] = *found;
                    d.file = pathOf(s, source);
                    d.line = line;
                    d.column = column;
                    d.includedFrom = chainOf(s, source);
                    return true;
                }
        return false;
    };
}

// A validator message at the OpLine before its instruction (words with the stage's source
// numbers as OpLine files, spirv_source_lines.hpp); else at the declaration it names.
SpirvSiteLocator lineLocator(const StageToValidate& s) {
    return [&s, byName = declarationLocator(s)](const SpirvSite& site, Diagnostic& d) {
        std::uint32_t source = 0;
        const auto* end = site.lineFile.data() + site.lineFile.size();
        if (site.line <= 0 || std::from_chars(site.lineFile.data(), end, source).ptr != end) return byName(site, d);
        d.file = pathOf(s, source);
        d.line = site.line;
        d.column = columnOf(SourceLines(s.resolved).find(source, site.line), "");
        d.includedFrom = chainOf(s, source);
        return true;
    };
}

// The validator's messages that found no declaration (a statement's) are located again in
// the same stage's SPIR-V made with line info, whose messages then replace them all.
void locateByLineInfo(const StageToValidate& s, glslang::TProgram& program, const std::string& what,
                      std::vector<Diagnostic>& invalid) {
    if (std::all_of(invalid.begin(), invalid.end(), [](const Diagnostic& d) { return d.line > 0; })) return;
    std::vector<std::uint32_t> words;
    std::string log;
    if (!generateSpirvWithSourceNumbers(program, glslangStage(s.stage), words, log)) return;
    auto located = validateSpirv(words, *s.rules.spirvEnv, s.path, what, lineLocator(s));
    if (!located.empty()) invalid = std::move(located);
}

// One stage's SPIR-V out of a linked `program`, checked by SPIRV-Tools, into `result`.
void emitStageSpirv(const StageToValidate& s, glslang::TProgram& program, ValidatedVariant& result) {
    const std::string what =
        "the " + std::string(catalog::stageName(s.stage)) + " stage of program '" + s.program + "'";
    StageSpirv out{s.stage, {}};
    std::string log;
    if (!generateSpirv(program, glslangStage(s.stage), out.words, log)) {
        result.diagnostics.push_back(makeError(s.path, 0, 0, "glslang made no SPIR-V of " + what + ": " + log));
        return;
    }
    auto invalid = validateSpirv(out.words, *s.rules.spirvEnv, s.path, what, declarationLocator(s));
    if (!invalid.empty()) locateByLineInfo(s, program, what, invalid);
    result.diagnostics.insert(result.diagnostics.end(), invalid.begin(), invalid.end());
    result.reflection.spirv.push_back(std::move(out));
}

// Links `program`; its link errors become diagnostics at `path`. False when it failed.
bool linkOrReport(glslang::TProgram& program, EShMessages messages, const std::string& path, ValidatedVariant& result) {
    if (program.link(messages)) return true;
    const auto before = result.diagnostics.size();
    std::istringstream log(program.getInfoLog());
    std::string line;
    while (std::getline(log, line))
        if (line.rfind("ERROR: ", 0) == 0)
            result.diagnostics.push_back(makeError(path, 0, 0, "link: " + line.substr(7)));
    if (result.diagnostics.size() == before)
        result.diagnostics.push_back(makeError(path, 0, 0, "glslang could not link the program"));
    return false;
}

// The program's layout from its stages' words (vulkan_reflection.hpp); words it cannot read,
// or an array size it cannot evaluate, are an error at the program's first stage.
void reflectStages(const StageToValidate& first, ValidatedVariant& result) {
    try {
        reflectSpirv(result.reflection);
    } catch (const std::exception& e) {
        result.diagnostics.push_back(
            makeError(first.path, 0, 0, std::string("cannot reflect the SPIR-V: ") + e.what()));
    }
}

// The Vulkan client: each stage linked in a program of its own, as glslc compiles it (the
// API links no blocks by name; where stages meet, checkInterfaces checked them), then its
// SPIR-V generated and validated; the program's layout is read from all stages' words.
void linkStageByStage(const std::vector<StageToValidate>& stages, const std::vector<glslang::TShader*>& shaders,
                      ValidatedVariant& result) {
    for (std::size_t i = 0; i < stages.size(); ++i) {
        glslang::TProgram program;
        program.addShader(shaders[i]);
        if (!linkOrReport(program, messagesFor(stages[i]), stages[i].path, result)) continue;
        emitStageSpirv(stages[i], program, result);
    }
    reflectStages(stages.front(), result);
}

// Links the program and reflects it into `result`; link errors become diagnostics.
void linkAndReflect(const std::vector<StageToValidate>& stages, const std::vector<glslang::TShader*>& shaders,
                    const Contract& contract, const LinkedProgramCheck& check, ValidatedVariant& result) {
    glslang::TProgram program;
    if (stages.front().rules.linksStageByStage) {
        linkStageByStage(stages, shaders, result);
    } else {
        for (auto* sh : shaders) program.addShader(sh);
        if (!linkOrReport(program, messagesFor(stages.front()), stages.front().path, result)) return;
        // glslang assigns the spirv target's locations and bindings here, before anything reads them.
        if (stages.front().rules.relaxedLayout && !assignLocations(stages, shaders, program, result)) return;
        if (stages.front().rules.spirvEnv) {
            for (const auto& s : stages) emitStageSpirv(s, program, result);
            reflectStages(stages.front(), result);
        } else {
            result.reflection = reflectProgram(program, contract);
        }
        if (check) {
            const auto found = check(program, shaders);
            result.diagnostics.insert(result.diagnostics.end(), found.begin(), found.end());
        }
    }
    result.ok = true;
    for (const auto& d : result.diagnostics) result.ok = result.ok && d.severity != Severity::Error;
}

}  // namespace

ValidatedVariant validateCompiledProgram(const std::vector<StageToValidate>& stages,
                                         const std::vector<std::shared_ptr<CompiledStage>>& compiledStages,
                                         const Contract& contract, const LinkedProgramCheck& check) {
    ValidatedVariant result;
    bool compiled = true;
    for (std::size_t i = 0; i < stages.size(); ++i) {
        const auto& c = *compiledStages[i];
        result.diagnostics.insert(result.diagnostics.end(), c.diagnostics.begin(), c.diagnostics.end());
        compiled = compiled && c.ok;
    }
    if (!compiled) return result;

    // Stages may be shared with programs on other threads: hold each one's lock, in
    // address order (no deadlock), while their glslang objects are read and linked.
    std::vector<CompiledStage*> order;
    for (const auto& c : compiledStages)
        if (std::find(order.begin(), order.end(), c.get()) == order.end()) order.push_back(c.get());
    std::sort(order.begin(), order.end());
    std::vector<std::unique_lock<std::mutex>> locks;
    for (auto* c : order) locks.emplace_back(c->mutex);
    std::vector<glslang::TShader*> shaders;
    for (const auto& c : compiledStages) shaders.push_back(c->shader.get());
    // glslang allocates from a per-thread pool that parse() and link() point at their
    // own; a stage parsed on another thread leaves this thread's pointing anywhere.
    glslang::TPoolAllocator pool;
    glslang::SetThreadPoolAllocator(&pool);

    const auto interfaceMessages = checkInterfaces(stages, shaders, contract);
    result.diagnostics.insert(result.diagnostics.end(), interfaceMessages.begin(), interfaceMessages.end());
    // glslang's own link check would only repeat these errors, with less detail; a
    // warning (a near miss of Prism's built-in contract) still links and reflects.
    const auto isError = [](const Diagnostic& d) { return d.severity == Severity::Error; };
    if (std::none_of(interfaceMessages.begin(), interfaceMessages.end(), isError))
        linkAndReflect(stages, shaders, contract, check, result);
    return result;
}

}  // namespace prism::shaderc
