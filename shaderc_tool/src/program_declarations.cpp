// Parsing and checking of `--program NAME=FILE[,FILE...]` (see program_declarations.hpp).
#include "program_declarations.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include "program_argument.hpp"
#include "stage_files.hpp"

namespace prism::shaderc {
namespace {

// What is wrong with a program name, "" when nothing.
std::string nameProblem(const std::string& name) {
    if (name.empty()) return "the program name before '=' is empty";
    if (name.find_first_of("/\\,:") != std::string::npos)  // ':' ends the shader of a --variant filter
        return "program name '" + name + "' contains '/', '\\', ',' or ':'; name the program, not a path";
    if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
        return "program name contains a control character";
    return {};
}

// One file of a declaration as a stage of `program`; false (with an error) when it is not one.
bool addStageFile(const std::string& file, const std::string& where, const SourceReader& reader, ShaderInput& program,
                  DeclaredPrograms& out) {
    auto error = [&](const std::string& message) {
        out.diagnostics.push_back(makeError(where, 0, 0, message));
        return false;
    };
    if (file.empty()) return error("an empty file name in the list; write NAME=FILE[,FILE...] without empty items");
    const auto stage = stageOfPath(file);
    if (!stage) return error("'" + file + "': unknown stage extension; use " + stageExtensionList());
    if (!reader.canonical(file)) {
        out.ioError = true;
        return error("'" + file + "': no such file");
    }
    for (const auto& s : program.stages)
        if (s.stage == *stage)
            return error("'" + s.path + "' and '" + file + "' are both " + std::string(catalog::stageName(*stage)) +
                         " stages; a program has one stage of each kind");
    program.stages.push_back({*stage, file});
    return true;
}

// One declaration, or nullopt (with errors) when it is malformed.
std::optional<ShaderInput> parseDeclaration(const std::string& text, const SourceReader& reader,
                                            const TargetRules& rules, DeclaredPrograms& out) {
    const std::string where = "--program " + text;
    const auto eq = text.find('=');
    if (eq == std::string::npos) {
        out.diagnostics.push_back(makeError(where, 0, 0, "expected NAME=FILE[,FILE...]"));
        return std::nullopt;
    }
    ShaderInput program{text.substr(0, eq), {}};
    if (auto problem = nameProblem(program.name); !problem.empty()) {
        out.diagnostics.push_back(makeError(where, 0, 0, problem));
        return std::nullopt;
    }
    bool ok = true;
    for (const auto& file : splitProgramFiles(text.substr(eq + 1)))
        ok = addStageFile(file, where, reader, program, out) && ok;
    if (!ok) return std::nullopt;
    sortByPipelineOrder(program.stages);
    const auto before = out.diagnostics.size();
    checkCompleteness(program, where, out.diagnostics, rules);
    if (out.diagnostics.size() != before) return std::nullopt;
    return program;
}

}  // namespace

DeclaredPrograms declaredPrograms(const std::vector<std::string>& declarations, const std::vector<ShaderInput>& taken,
                                  const SourceReader& reader, const TargetRules& rules) {
    DeclaredPrograms out;
    std::set<std::string> names;
    for (const auto& p : taken) names.insert(p.name);
    for (const auto& text : declarations) {
        auto program = parseDeclaration(text, reader, rules, out);
        if (!program) continue;
        if (!names.insert(program->name).second) {
            out.diagnostics.push_back(makeError("--program " + text, 0, 0,
                                                "program '" + program->name +
                                                    "' is declared twice (by another --program or by same-name "
                                                    "stage files in an input folder); give each program its own name"));
            continue;
        }
        out.programs.push_back(std::move(*program));
    }
    return out;
}

std::set<std::string> filesNamedBy(const std::vector<std::string>& declarations, const SourceReader& reader) {
    std::set<std::string> named;
    for (const auto& text : declarations) {
        const auto eq = text.find('=');
        if (eq == std::string::npos) continue;
        for (const auto& file : splitProgramFiles(text.substr(eq + 1)))
            if (auto canonical = reader.canonical(file)) named.insert(*canonical);
    }
    return named;
}

}  // namespace prism::shaderc
