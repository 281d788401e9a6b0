// libFuzzer harness: the Vulkan client (prism-shaderc --client vulkan) on in-memory files.
// The input is up to three parts separated by a line "//--file": two stages and the module
// lib/user.glsl they may include. The first stage's first line picks the program's kinds:
// `//mesh` a mesh + fragment program, `//comp` a compute stage, `//rgen` a ray-generation
// stage alone, `//rtprog` a ray-generation + closest-hit program, `//vert` a vertex stage
// alone (a depth-only pipeline), anything else a vertex + fragment program. So the Vulkan
// linking rules (stage by stage; stage interfaces by location, mesh to fragment included;
// descriptors by set and binding; ray-tracing data by location) and the block layout rules
// a stage's #extension lines select for SPIRV-Tools are all reached.
// Oracle: no crash, leak, undefined behaviour or hang in glslang's Vulkan front end, its
// SPIR-V generator, SPIRV-Tools' validator or the SPIR-V reflection; a program validated
// without errors has one SPIR-V module per stage, each starting with the magic number and
// accepted again by validateSpirv; every error names a file; an error between two stages'
// declarations has a note at the other declaration, which names a file too.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "include_resolver.hpp"
#include "spirv_codegen.hpp"
#include "validator.hpp"

using namespace prism::shaderc;
using prism::catalog::Stage;

namespace {

std::vector<Stage> kindsOf(const std::string& first) {
    if (first.rfind("//mesh", 0) == 0) return {Stage::Mesh, Stage::Fragment};
    if (first.rfind("//comp", 0) == 0) return {Stage::Compute};
    if (first.rfind("//rgen", 0) == 0) return {Stage::RayGen};
    if (first.rfind("//rtprog", 0) == 0) return {Stage::RayGen, Stage::ClosestHit};
    if (first.rfind("//vert", 0) == 0) return {Stage::Vertex};
    return {Stage::Vertex, Stage::Fragment};
}

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "vulkan client: %s\n", what);
    std::abort();
}

void checkResult(const ValidatedVariant& result, const std::vector<StageToValidate>& stages) {
    for (const auto& d : result.diagnostics) {
        if (d.severity == Severity::Error && d.file.empty()) fail("an error names no file");
        if (d.message.find("make both declarations agree") == std::string::npos) continue;
        if (d.notes.empty() || d.notes.front().file.empty()) fail("a cross-stage error has no note at the other stage");
    }
    if (!result.ok) return;
    if (result.reflection.spirv.size() != stages.size()) fail("a valid program lacks a stage's SPIR-V");
    for (const auto& s : result.reflection.spirv) {
        if (s.words.size() < 5 || s.words[0] != 0x07230203u) fail("SPIR-V without its magic number");
        if (!validateSpirv(s.words, SpirvEnv::Vulkan1_2, "fuzz", "a stage").empty())
            fail("a valid program's SPIR-V fails validation");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool initialized = [] {
        initializeValidator();
        return true;
    }();
    (void)initialized;
    const auto parts = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n//--file\n", 3);
    const auto kinds = kindsOf(parts[0]);
    MemoryReader files;
    if (parts.size() > 2) files.add("lib/user.glsl", parts[2]);
    ResolveOptions options;
    options.includeDirs = {"lib"};
    options.defaultVersion = "#version 450";
    std::vector<StageToValidate> stages;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        const std::string path = "s/p." + std::string(prism::catalog::stageName(kinds[i]));
        files.add(path, i < parts.size() && i < 2 ? parts[i] : std::string("#version 450\nvoid main() {}\n"));
        auto resolved = resolveStage(path, options, files);
        if (!resolved.ok) return 0;
        stages.push_back({kinds[i], path, resolved.stage, vulkanClientRules(SpirvEnv::Vulkan1_2), "p"});
    }
    checkResult(validateProgram(stages, {}), stages);
    return 0;
}
