// libFuzzer harness: prism-shaderc's include resolver and its #if evaluation on
// in-memory files. The input is up to three files separated by a line "//--file":
// the stage main.frag, then lib/user_a.glsl and lib/user_b.glsl, which sit beside a
// small fixed module set (plain, guarded, #pragma once, a diamond, a cycle, an include
// under #if). Kept thin on purpose: resolveStage and scanModule are the public entry
// points, so this file follows the resolver when it is rewritten (issue 17).
// Oracle: no crash, leak, undefined behaviour, hang or escaping exception, and a
// failed resolve always says why.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "include_resolver.hpp"

using namespace prism::shaderc;

namespace {

const MemoryReader& baseModules() {
    static const MemoryReader files{
        {"lib/plain.glsl", "// A plain module.\nfloat plain(float x) { return x * 2.0; }\n"},
        {"lib/guarded.glsl",
         "#ifndef GUARDED_GLSL\n#define GUARDED_GLSL\n#define GUARD_VALUE 3\nfloat guarded() { return 1.0; "
         "}\n#endif\n"},
        {"lib/once.glsl", "#pragma once\n#include \"plain.glsl\"\nfloat once() { return plain(1.0); }\n"},
        {"lib/left.glsl", "#include \"base.glsl\"\nfloat left() { return base(); }\n"},
        {"lib/right.glsl", "#include <base.glsl>\nfloat right() { return base(); }\n"},
        {"lib/base.glsl", "#version 330 core\nfloat base() { return 0.5; }\n"},
        {"lib/cycle_a.glsl", "#include \"cycle_b.glsl\"\n"},
        {"lib/cycle_b.glsl", "#include \"cycle_a.glsl\"\n"},
        {"lib/conditional.glsl",
         "#if defined(FAST) && FAST > 1 || (GUARD_VALUE << 2) == 12\n#include \"plain.glsl\"\n#elif "
         "__VERSION__ >= 400\n#include \"missing.glsl\"\n#else\n#include \"once.glsl\"\n#endif\n"},
        {"lib/variant.glsl", "#pragma prism variant LIGHTS 1 2 4\n#pragma prism variant FOG\n"},
    };
    return files;
}

void check(bool ok, const std::vector<Diagnostic>& diagnostics) {
    bool anyError = false;
    for (const auto& d : diagnostics) anyError = anyError || d.severity == Severity::Error;
    if (!ok && !anyError) {
        std::fprintf(stderr, "resolve failed without an error diagnostic\n");
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n//--file\n", 3);
    MemoryReader files = baseModules();
    files.add("main.frag", parts[0]);
    if (parts.size() > 1) files.add("lib/user_a.glsl", parts[1]);
    if (parts.size() > 2) files.add("lib/user_b.glsl", parts[2]);

    ResolveOptions options;
    options.includeDirs = {"lib"};
    options.defines = {{"FAST", "2"}, {"EMPTY", ""}};
    const ResolveResult stage = resolveStage("main.frag", options, files);
    check(stage.ok, stage.diagnostics);

    if (parts.size() > 1) {
        const ModuleScanResult module = scanModule("lib/user_a.glsl", options, files);
        check(module.ok, module.diagnostics);
    }
    return 0;
}
