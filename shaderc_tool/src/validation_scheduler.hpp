// Stage 5 of prism-shaderc: validates every variant of the catalogue for the gl target
// with as little glslang work as the results allow (one program: validator.hpp), on the
// scheduler every target shares (target_scheduler.hpp: token groups validated once, clean
// results only shared and cached, a private run for a program whose result has messages).
// Each distinct stage (kind, #version, token stream) of the groups' first runs is parsed
// once and shared by the programs that need it (shared_stage_parses.hpp).
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
    std::size_t fromCache = 0;       // distinct keys answered by the cache (clean results only)
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

// The content key of one variant's program (the targets' schedule and tests use it too).
ProgramKey programKey(const ResolvedCatalog& catalog, const Contract& contract, std::size_t shader,
                      std::size_t variant);

}  // namespace prism::shaderc
