// In-process rebuild of one variant through prism_shaderc_lib (see shader_rebuild.hpp).
#include "shader_rebuild.hpp"

#include "contract.hpp"
#include "diagnostics.hpp"
#include "include_resolver.hpp"
#include "source_reader.hpp"
#include "validator.hpp"

namespace prism::render::detail {

namespace sc = prism::shaderc;

struct ShaderRebuilder::State {
    sc::Contract contract;
};

ShaderRebuilder::ShaderRebuilder(std::vector<std::string> contractFiles)
    : contractFiles_(std::move(contractFiles)), state_(std::make_unique<State>()) {
    sc::initializeValidator();  // glslang counts its clients: safe beside other users
}

ShaderRebuilder::~ShaderRebuilder() {
    sc::finalizeValidator();
}

std::vector<std::string> ShaderRebuilder::loadContract() {
    sc::DiskReader disk;  // a fresh reader: its cache would hide the edit
    auto loaded = sc::loadContracts(contractFiles_, disk);
    std::vector<std::string> errors;
    bool failed = loaded.ioError;
    for (const auto& d : loaded.diagnostics) {
        failed = failed || d.severity == sc::Severity::Error;
        errors.push_back(sc::formatDiagnostic(d, sc::ErrorFormat::Gcc));
    }
    if (!failed) {
        state_->contract = std::move(loaded.contract);
        errors.clear();
    }
    return errors;
}

RebuildOutcome ShaderRebuilder::rebuild(const RebuildRequest& request) const {
    RebuildOutcome out;
    sc::DiskReader disk;  // per rebuild: sees every edit, reads each file once
    sc::DiagnosticSink sink;
    sc::ResolveOptions options{request.includeDirs, request.defines, request.versionDirective, {}};

    std::vector<sc::StageToValidate> stages;
    bool resolved = true;
    for (const auto& st : request.stages) {
        auto r = sc::resolveStage(st.path, options, disk);
        sink.reportAll(std::move(r.diagnostics));
        out.filesRead.insert(out.filesRead.end(), r.stage.filesRead.begin(), r.stage.filesRead.end());
        resolved = resolved && r.ok;
        stages.push_back({st.stage, st.path, std::move(r.stage)});
    }
    if (resolved && sink.errorCount() == 0) {
        auto validated = sc::validateProgram(stages, state_->contract);
        sink.reportAll(std::move(validated.diagnostics));
        if (validated.ok && sink.errorCount() == 0) {
            gl::ProgramSources sources;
            sources.label = request.label;
            for (const auto& st : stages) {
                gl::StageText text;
                text.stage = st.stage;
                text.source = st.resolved.text;
                for (const auto& f : st.resolved.files) text.files.push_back({f.number, f.path});
                sources.stages.push_back(std::move(text));
            }
            for (const auto& a : state_->contract.attributes) sources.attributes.push_back({a.name, a.location});
            std::vector<gl::UniformDecl> uniforms;
            for (const auto& u : validated.reflection.uniforms) uniforms.push_back({u.name, u.glType, u.arraySize});
            sources.uniforms = std::move(uniforms);
            out.sources = std::move(sources);
        }
    }
    for (const auto& d : sink.diagnostics())
        if (d.severity == sc::Severity::Error) out.diagnostics.push_back(sc::formatDiagnostic(d, sc::ErrorFormat::Gcc));
    if (!out.sources && out.diagnostics.empty())
        out.diagnostics.push_back(request.label + ": error: the shader tool rejected the program without a message\n");
    return out;
}

}  // namespace prism::render::detail
