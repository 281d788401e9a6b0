// libFuzzer harness, differential: one shader through prism-shaderc's three targets (gl,
// es300, spirv; docs/targets.md) as the tool runs them (resolveCatalog, then the gl
// validation, validateEs300 and buildSpirvTarget), on in-memory files. The input is up to
// three parts separated by a line "//--file": the stages s/p.vert and s/p.frag and the
// module lib/user.glsl they may include; `#pragma prism variant` and `#pragma prism targets`
// in them work as in any shader.
// Oracle: when the tool accepts the input without an error, then, checked here again with
// glslang and SPIRV-Tools directly (not through the tool's own calls, nor its memo of
// accepted modules): every variant produced for es300 has both stages' es300 texts compile
// as GLSL ES 3.00 and link; every variant produced for spirv has one module per stage that
// SPIRV-Tools' validator accepts for Vulkan 1.1. Plus no crash, leak, undefined behaviour
// or hang. Anything else aborts: a finding.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <spirv-tools/libspirv.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "es300_target.hpp"
#include "fuzz_input.hpp"
#include "shader_targets.hpp"
#include "spirv_target.hpp"
#include "validation_scheduler.hpp"

using namespace prism::shaderc;
using prism::catalog::Stage;

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "targets: %s\n%s\n", what, detail.c_str());
    std::abort();
}

// glslang itself, as glslangValidator -l would run it on the emitted es300 files.
void expectEs300Links(const std::vector<ResolvedStage>& desktop, const std::vector<Stage>& kinds) {
    std::vector<std::unique_ptr<glslang::TShader>> shaders;
    glslang::TProgram program;
    for (std::size_t i = 0; i < desktop.size(); ++i) {
        const std::string es = es300Stage(desktop[i]).text;
        auto shader = std::make_unique<glslang::TShader>(kinds[i] == Stage::Vertex ? EShLangVertex : EShLangFragment);
        const char* text = es.c_str();
        shader->setStrings(&text, 1);
        if (!shader->parse(GetDefaultResources(), 300, EEsProfile, false, false, EShMsgDefault))
            fail("an accepted es300 stage does not compile as GLSL ES 3.00", es + shader->getInfoLog());
        program.addShader(shader.get());
        shaders.push_back(std::move(shader));
    }
    if (!program.link(EShMsgDefault)) fail("an accepted es300 program does not link", program.getInfoLog());
}

void expectValidSpirv(const ProgramReflection& spirv, std::size_t stages) {
    if (spirv.spirv.size() != stages) fail("an accepted spirv program lacks a stage's module", "");
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string messages;
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* m) {
        messages += std::string(m) + "\n";
    });
    for (const auto& module : spirv.spirv)
        if (!tools.Validate(module.words.data(), module.words.size()))
            fail("an accepted spirv module fails SPIRV-Tools' validator", messages);
}

ResolvedCatalog resolved(const std::vector<std::string>& parts, const Options& o, std::vector<Stage>& kinds) {
    MemoryReader files;
    ShaderInput input{"p", {}};
    const std::string kEmpty = "#version 330 core\nvoid main() {}\n";
    for (const Stage kind : {Stage::Vertex, Stage::Fragment}) {
        const std::size_t i = kinds.size();
        const std::string path = "s/p." + std::string(prism::catalog::stageName(kind));
        files.add(path, i < parts.size() && i < 2 ? parts[i] : kEmpty);
        input.stages.push_back({kind, path});
        kinds.push_back(kind);
    }
    if (parts.size() > 2) files.add("lib/user.glsl", parts[2]);
    return resolveCatalog(o, {input}, {}, files);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Held for the whole run, so glslang's built-in tables outlive the tool's own
    // initialise/finalise pairs and are built once.
    static const bool initialized = glslang::InitializeProcess();
    (void)initialized;
    const auto parts = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n//--file\n", 3);
    Options o;
    o.includeDirs = {"lib"};
    o.baseDir = "/";  // as parseArgs makes it: absolute (the files are in memory)
    o.targets = {Target::Gl, Target::Es300, Target::Spirv};
    o.jobs = 1;
    o.cacheDir = "none";
    std::vector<Stage> kinds;
    auto rc = resolved(parts, o, kinds);
    DiagnosticSink sink;
    sink.reportAll(rc.diagnostics);
    if (sink.errorCount() == 0) sink.reportAll(checkShaderTargets(o, rc));
    if (sink.errorCount() == 0) sink.reportAll(validateCatalog(o, rc, {}).diagnostics);
    if (sink.errorCount() == 0) sink.reportAll(validateEs300(o, rc, {}));
    if (sink.errorCount() == 0) sink.reportAll(buildSpirvTarget(o, rc, {}));
    if (sink.errorCount() > 0 || rc.data.shaders.empty()) return 0;

    const auto& variants = rc.data.shaders[0].variants;
    for (std::size_t v = 0; v < variants.size(); ++v) {
        if (producedFor(o, rc, 0, Target::Es300)) {
            if (!variants[v].es300) fail("a variant produced for es300 is not marked as such", variants[v].name);
            expectEs300Links(rc.resolved[0][v], kinds);
        }
        if (producedFor(o, rc, 0, Target::Spirv)) {
            if (!variants[v].spirv) fail("a variant produced for spirv has no SPIR-V", variants[v].name);
            expectValidSpirv(*variants[v].spirv, kinds.size());
        }
    }
    return 0;
}
