// Stage 5 of prism-shaderc: validates every variant of the catalogue with as little
// glslang work as the results allow (one program: validator.hpp).
//   1. Each program gets a content key (validation_cache.hpp) from its stages'
//      validation keys (validation_key.hpp); programs with the same token stream are
//      validated once.
//   2. Keys found in the cache (--cache-dir) are not validated at all.
//   3. The rest run on `jobs` threads (glslang is initialised once per process and is
//      thread-safe per TShader/TProgram): each distinct stage (kind, #version, token
//      stream) is parsed by the first program that needs it, shared by the others and
//      freed after the last, each program is linked and checked, and the results are
//      stored.
// A shared result is reused only when it has no diagnostics; a program whose result
// has some is validated with its own text, so every message keeps its own lines.
//
//   if (sink.errorCount() == 0) sink.reportAll(validateCatalog(options, catalog, contract).diagnostics);
#pragma once

#include <cstddef>

#include "catalog_builder.hpp"
#include "validation_cache.hpp"

namespace prism::shaderc {

struct ValidationStats {
    std::size_t programs = 0;        // variants in the catalogue
    std::size_t distinct = 0;        // distinct token keys among them
    std::size_t fromCache = 0;       // distinct keys answered by the cache
    std::size_t validated = 0;       // glslang validations run (distinct keys + programs re-run for their own lines)
    std::size_t stagesCompiled = 0;  // distinct stages parsed for them (shared by programs)
    double ms = 0;                   // wall clock
};

struct Validation {
    ValidationStats stats;
    std::vector<Diagnostic> diagnostics;  // every program's, in catalogue order (repeats dropped)
};

// The stage: validateCatalogScheduled with the cache the options name (--cache-dir), and
// under --stats the resolution's and the validation's counts on stderr.
Validation validateCatalog(const Options& options, ResolvedCatalog& catalog, const Contract& contract);

// Fills in every variant's reflection and reports the diagnostics of every program.
ValidationStats validateCatalogScheduled(ResolvedCatalog& catalog, const Contract& contract, int jobs,
                                         ValidationCache& cache, DiagnosticSink& sink);

// The other targets schedule their programs in target_scheduler.hpp, on the same keys.

// The content key of one variant's program (the targets' schedule and tests use it too).
ProgramKey programKey(const ResolvedCatalog& catalog, const Contract& contract, std::size_t shader,
                      std::size_t variant);

}  // namespace prism::shaderc
