// Stage 4 of prism-shaderc: builds the catalogue: for every shader, resolves its stages,
// derives its variant axes, then resolves every chosen variant (in parallel, -j), and
// gathers the modules of the include directories with their dependencies. Validation is
// stage 5 (validation_scheduler.hpp).
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "catalog_model.hpp"
#include "diagnostics.hpp"
#include "shader_inputs.hpp"
#include "source_reader.hpp"

namespace prism::shaderc {

// Resolved (not yet validated) catalogue: cheap to compute, and enough to know
// whether anything changed since the header was last written.
struct ResolvedCatalog {
    CatalogData data;                                               // variants without reflection yet
    std::vector<std::string> filesRead;                             // for the depfile (display paths)
    std::vector<std::vector<std::vector<ResolvedStage>>> resolved;  // [shader][variant][stage]
    std::vector<std::vector<std::string>> stagePaths;               // [shader][stage]
    std::size_t preprocessorRuns = 0;     // runs of glslang's preprocessor (variant_resolution.hpp)
    double builtInsMs = 0;                // glslang's built-in tables, timed apart under --stats
    double resolveMs = 0;                 // the whole resolution, wall clock
    std::vector<Diagnostic> diagnostics;  // the resolution's, in order (repeats dropped)
};

ResolvedCatalog resolveCatalog(const Options& options, const std::vector<ShaderInput>& shaders,
                               const Contract& contract, const SourceReader& reader);

// A stable fingerprint of everything that determines the header's content.
std::string fingerprint(const ResolvedCatalog& catalog);

// The sources block and banner fingerprint the data file prints (byte for byte those of
// the golden files; nothing reads them back: the run record, up_to_date.hpp, decides).
void fillDataFileRecord(const Options& options, ResolvedCatalog& catalog, const SourceReader& reader);

}  // namespace prism::shaderc
