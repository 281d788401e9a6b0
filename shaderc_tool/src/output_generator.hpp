// Stage 6's one interface for an output (after sokol-shdc's Generator): each output the
// catalogue can be written as (the C++ header and its data file, the web catalogue, the
// --emit-glsl texts, the --emit-spirv files, the --emit-reflection JSON) is one
// OutputGenerator in a file of its own (generator_*.cpp), and outputGenerators() lists them
// in the order the output stage (outputs.cpp) runs them. A generator only computes: it
// returns every file it makes, path and bytes, and the output stage writes them
// (output_file.hpp: only what changed, atomically). The build system's files (depfile,
// stamp) are not generators: every successful run writes them, a no-op included.
//
// Adding an output: one new file, generator_<name>.cpp, with its OutputGenerator subclass and
// make<Name>Generator(), and its registration in output_generators.cpp (the function's
// declaration and its entry in the list); no other stage branches on it.
//
//   for (const auto& g : outputGenerators())
//       for (const std::string& path : g->pathsNamed(options)) ...;  // what a run with `options` writes
//   for (const GeneratedFile& f : generator.generate(options, catalog)) writeIfChanged(f.path, f.bytes, error);
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"

namespace prism::shaderc {

struct GeneratedFile {
    std::string path;
    std::string bytes;
};

class OutputGenerator {
  public:
    virtual ~OutputGenerator() = default;
    // Its name in messages, e.g. "web catalogue".
    virtual std::string_view name() const = 0;
    // The paths the options name for this output, known before any input is read: its files
    // (the header's: the header and its data file), or the one directory it writes its files
    // into (--emit-glsl, --emit-spirv). Empty: the options do not ask for it, and
    // generate() is not called.
    virtual std::vector<std::string> pathsNamed(const Options& options) const = 0;
    // Every file it makes for the validated catalogue, in the order they are written; each
    // path is one of pathsNamed(options) or inside one of them.
    virtual std::vector<GeneratedFile> generate(const Options& options, const ResolvedCatalog& catalog) const = 0;
};

// The registered generators, in the order the output stage runs them.
const std::vector<std::unique_ptr<OutputGenerator>>& outputGenerators();

// Every path the options name for an output, over all generators (OutputGenerator::pathsNamed):
// what a record of "nothing changed" checks before reading any input.
std::vector<std::string> outputPathsNamed(const Options& options);

}  // namespace prism::shaderc
