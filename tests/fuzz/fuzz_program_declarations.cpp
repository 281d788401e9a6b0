// libFuzzer harness: `--program NAME=FILE[,FILE...]` declarations (program_declarations.hpp),
// one per input line, over in-memory stage files of every kind. Oracle: no crash, leak,
// undefined behaviour or escaping exception; every accepted program has a name that
// mangles to an identifier demangling back to it, known files, one stage of each kind
// in pipeline order, a vertex, compute or mesh stage, a name no other program has, and files
// that filesNamedBy() lists (so an input folder does not pair them by name too).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "fuzz_input.hpp"
#include "module_naming.hpp"
#include "program_argument.hpp"
#include "program_declarations.hpp"

using namespace prism::shaderc;
using prism::catalog::Stage;

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "%s: '%s'\n", what, detail.c_str());
    std::abort();
}

void checkProgram(const ShaderInput& p, const MemoryReader& files, std::set<std::string>& names) {
    if (p.name.empty() || !names.insert(p.name).second) fail("empty or repeated program name", p.name);
    if (demangleName(mangleName(p.name)) != p.name) fail("name does not demangle back", p.name);
    bool entryStage = false;  // what a pipeline starts from: a vertex, compute or mesh stage
    for (std::size_t i = 0; i < p.stages.size(); ++i) {
        if (!files.canonical(p.stages[i].path)) fail("unknown file accepted", p.stages[i].path);
        if (i > 0 && pipelineOrder(p.stages[i - 1].stage) >= pipelineOrder(p.stages[i].stage))
            fail("stages out of pipeline order or repeated", p.name);
        const Stage s = p.stages[i].stage;
        entryStage = entryStage || s == Stage::Vertex || s == Stage::Compute || s == Stage::Mesh;
    }
    if (!entryStage) fail("program without a vertex, compute or mesh stage", p.name);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const MemoryReader files{{"a.vert", "v"}, {"b.frag", "f"}, {"c.tesc", "c"},   {"d.tese", "e"},
                                    {"e.geom", "g"}, {"f.comp", "k"}, {"s/a.vert", "v"}, {"x.mesh", "m"}};
    const auto declarations = prism::fuzz::splitParts(prism::fuzz::text(data, size), "\n", 64);
    const DeclaredPrograms declared = declaredPrograms(declarations, {}, files);
    std::set<std::string> names;
    const auto named = filesNamedBy(declarations, files);
    for (const auto& p : declared.programs) {
        checkProgram(p, files, names);
        for (const auto& s : p.stages)
            if (!named.contains(*files.canonical(s.path)))
                fail("a program's file is not among the named files", s.path);
    }
    for (const auto& d : declarations)
        if (declarationWithPaths(d, [](const std::string& path) { return path; }) != d)
            fail("rewriting paths as themselves changed the declaration", d);
    return 0;
}
