// In-process rebuild of one variant through the build step's library (see shader_rebuild.hpp).
#include "shader_rebuild.hpp"

#include <algorithm>

#include "prism/shaderc/build_step.hpp"

namespace prism::render::detail {

namespace sc = prism::shaderc;

namespace {

gl::ProgramSources sourcesOf(const std::string& label, const std::vector<sc::StageToCheck>& stages,
                             const sc::BindingContract& contract, const sc::ProgramCheck& checked) {
    gl::ProgramSources sources;
    sources.label = label;
    for (const auto& st : stages) {
        gl::StageText text;
        text.stage = st.stage;
        text.source = st.resolved.text;
        for (std::uint32_t n = 0; n < st.resolved.files.size(); ++n) text.files.push_back({n, st.resolved.files[n]});
        sources.stages.push_back(std::move(text));
    }
    for (const auto& a : contract.attributes) sources.attributes.push_back({a.name, a.location});
    std::vector<gl::UniformDecl> uniforms;
    for (const auto& u : checked.uniforms) uniforms.push_back({u.name, u.glType, u.arraySize});
    sources.uniforms = std::move(uniforms);
    return sources;
}

}  // namespace

struct ShaderRebuilder::State {
    sc::Validator validator;  // glslang counts its clients: safe beside other users
    sc::BindingContract contract;
};

ShaderRebuilder::ShaderRebuilder(std::vector<std::string> contractFiles)
    : contractFiles_(std::move(contractFiles)), state_(std::make_unique<State>()) {}

ShaderRebuilder::~ShaderRebuilder() = default;

std::vector<std::string> ShaderRebuilder::loadContract() {
    auto loaded = sc::loadContract(contractFiles_, sc::Files::disk());  // a fresh reader sees the edit
    std::vector<std::string> errors;
    if (loaded.ok) {
        state_->contract = std::move(loaded.contract);
        return errors;
    }
    for (const auto& m : loaded.messages) errors.push_back(m.text);
    return errors;
}

RebuildOutcome ShaderRebuilder::rebuild(const RebuildRequest& request) const {
    RebuildOutcome out;
    const sc::Files disk = sc::Files::disk();  // per rebuild: sees every edit, reads each file once
    const sc::ResolveSettings settings{request.includeDirs, request.defines, request.versionDirective, {}};
    std::vector<sc::Message> messages;
    std::vector<sc::StageToCheck> stages;
    bool resolved = true;
    for (const auto& st : request.stages) {
        auto r = sc::resolveStage(st.path, settings, disk);
        messages.insert(messages.end(), r.messages.begin(), r.messages.end());
        out.filesRead.insert(out.filesRead.end(), r.resolved.filesRead.begin(), r.resolved.filesRead.end());
        resolved = resolved && r.ok;
        stages.push_back({st.stage, st.path, std::move(r.resolved)});
    }
    if (resolved && !sc::hasError(messages)) {
        auto checked = sc::checkProgram(stages, state_->contract);
        messages.insert(messages.end(), checked.messages.begin(), checked.messages.end());
        if (checked.ok) out.sources = sourcesOf(request.label, stages, state_->contract, checked);
    }
    for (const auto& m : messages)
        if (m.error && std::find(out.diagnostics.begin(), out.diagnostics.end(), m.text) == out.diagnostics.end())
            out.diagnostics.push_back(m.text);
    if (!out.sources && out.diagnostics.empty())
        out.diagnostics.push_back(request.label + ": error: the shader tool rejected the program without a message\n");
    return out;
}

}  // namespace prism::render::detail
