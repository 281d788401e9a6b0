// libFuzzer harness: variant sharing (variant_resolution.hpp) against every variant's own
// glslang run, on in-memory files. The input is up to three files separated by a line
// "//--file": the stage main.frag, then lib/user_a.glsl and lib/user_b.glsl, beside a
// small fixed module set. Axes A (0 1), B (0 1 2) and K (ONE TWO, values that name
// macros of lib/values.glsl) give 12 variants, resolved once with sharing (from the base
// run, as prism-shaderc does) and once without.
// Oracle: where a variant's own run reports no error, the shared result is the same
// flattened text, files, include chains and variant pragmas, and gets the same
// validation key; plus no crash, leak, undefined behaviour or hang.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "include_resolver.hpp"
#include "variant_resolution.hpp"

using namespace prism::shaderc;

namespace {

MemoryReader withBaseModules() {
    return MemoryReader{
        {"lib/values.glsl", "// The values of K.\n#define ONE 1\n#define TWO 2\n"},
        {"lib/x.glsl", "// Taken when USE_X.\nfloat x() { return 1.0; }\n"},
        {"lib/chain.glsl",
         "// A condition that defines what another tests.\n#if A == 1\n#define USE_X\n#endif\n"
         "#ifdef USE_X\n#include \"x.glsl\"\n#endif\n"},
        {"lib/guarded.glsl",
         "#ifndef GUARDED\n#define GUARDED\n#if B > 1\n#include \"values.glsl\"\n#endif\n"
         "float g() { return float(B); }\n#endif\n"},
        {"lib/once.glsl", "#pragma once\n#pragma prism variant A 0 1\nfloat once() { return float(A); }\n"},
    };
}

std::vector<VariantChoice> choices() {
    std::vector<VariantChoice> all;
    for (const char* a : {"0", "1"})
        for (const char* b : {"0", "1", "2"})
            for (const char* k : {"ONE", "TWO"})
                all.push_back({std::string("A=") + a + ",B=" + b + ",K=" + k, {{"A", a}, {"B", b}, {"K", k}}});
    return all;
}

bool sameFiles(const ResolvedStage& a, const ResolvedStage& b) {
    if (a.files.size() != b.files.size() || a.filesRead != b.filesRead) return false;
    for (std::size_t i = 0; i < a.files.size(); ++i) {
        if (a.files[i].path != b.files[i].path || a.files[i].chain.size() != b.files[i].chain.size()) return false;
        for (std::size_t c = 0; c < a.files[i].chain.size(); ++c)
            if (a.files[i].chain[c].file != b.files[i].chain[c].file ||
                a.files[i].chain[c].line != b.files[i].chain[c].line)
                return false;
    }
    if (a.variantPragmas.size() != b.variantPragmas.size()) return false;
    for (std::size_t i = 0; i < a.variantPragmas.size(); ++i)
        if (a.variantPragmas[i].name != b.variantPragmas[i].name ||
            a.variantPragmas[i].values != b.variantPragmas[i].values)
            return false;
    return true;
}

[[noreturn]] void fail(const char* what, const VariantChoice& choice, const std::string& shared,
                       const std::string& own) {
    std::fprintf(stderr, "variant sharing: %s differs for %s\n--- shared:\n%s\n--- own run:\n%s\n", what,
                 choice.name.c_str(), shared.c_str(), own.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n//--file\n", 3);
    MemoryReader files = withBaseModules();
    files.add("main.frag", parts[0]);
    if (parts.size() > 1) files.add("lib/user_a.glsl", parts[1]);
    if (parts.size() > 2) files.add("lib/user_b.glsl", parts[2]);

    ResolveOptions base;
    base.includeDirs = {"lib"};
    base.defines = {{"FAST", "2"}};
    const std::vector<std::string> stages{"main.frag"};
    const std::vector<ResolveResult> baseRuns{resolveStage("main.frag", base, files)};
    if (!baseRuns[0].ok) return 0;  // prism-shaderc stops at a failing base run
    const auto all = choices();
    const auto shared = resolveVariants(stages, base, all, files, 1, baseRuns, true);
    const auto own = resolveVariants(stages, base, all, files, 1, {}, false);
    for (std::size_t v = 0; v < all.size(); ++v) {
        const ResolveResult& s = shared[v][0];
        const ResolveResult& o = own[v][0];
        bool ownError = !o.ok;
        for (const auto& d : o.diagnostics) ownError = ownError || d.severity == Severity::Error;
        if (ownError) continue;  // a shared run's code is still compiled by glslang itself
        if (!s.ok) fail("success", all[v], "failed", "ok");
        if (s.stage.text != o.stage.text) fail("the flattened text", all[v], s.stage.text, o.stage.text);
        if (!sameFiles(s.stage, o.stage)) fail("the files", all[v], s.stage.text, o.stage.text);
        if (s.stage.validationKey != o.stage.validationKey)
            fail("the validation key", all[v], s.stage.validationKey, o.stage.validationKey);
    }
    return 0;
}
