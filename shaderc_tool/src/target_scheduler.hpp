// Part of stage 5: how every target (gl, es300, spirv) schedules the validation of its
// programs. Programs with one token key (programKey) are validated once; a clean result
// found in the target's cache pack (--cache-dir, validation_cache.hpp) is not validated
// again, so a check after an edit validates, for every target, only the programs whose
// token streams changed.
// Cache policy, one for all targets: only clean results (no message of any kind) are
// shared by a group, stored or taken from the cache. A result with messages is never
// shared or cached: each program that has it runs itself on every check, so every message
// speaks of its own lines and its own program, and a warning is never lost to a cache hit.
//
//   TargetPrograms scheduled = scheduleTarget(options, catalog, contract, Target::Spirv, programs);
//   for (std::size_t i : scheduled.firstRuns()) prepare(i);  // e.g. the stages to share parses of
//   auto diagnostics = runTarget(scheduled, options.jobs,
//       [&](std::size_t i, bool groupRun) { return validate(i); },
//       [&](std::size_t i, const ValidatedVariant& result) { keep(i, result); });
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "args.hpp"
#include "catalog_builder.hpp"
#include "targets.hpp"
#include "validation_cache.hpp"

namespace prism::shaderc {

struct TargetPrograms {
    Target target = Target::Gl;
    std::vector<std::pair<std::size_t, std::size_t>> programs;  // (shader, variant)
    std::vector<ProgramKey> keys;
    std::vector<std::size_t> representatives;             // [i]: the first program with i's token key
    std::vector<std::optional<ValidatedVariant>> cached;  // representatives' clean results from the cache
    std::unique_ptr<ValidationCache> ownCache;            // the pack scheduleTarget opened, if it did
    ValidationCache* cache = nullptr;                     // the pack in use
    std::size_t validated = 0;                            // validations runTarget ran (first and own runs)

    bool runsFirst(std::size_t i) const { return representatives[i] == i && !cached[i]; }
    std::vector<std::size_t> firstRuns() const;
    std::size_t fromCache() const;
};

// Keys the programs and looks their groups up in the target's own cache pack: the
// catalogue's pack for gl, `<catalogue key>-<target>` beside it for the others.
TargetPrograms scheduleTarget(const Options& options, const ResolvedCatalog& catalog, const Contract& contract,
                              Target target, std::vector<std::pair<std::size_t, std::size_t>> programs);
// The same with the cache to use (it must outlive the result), keying on `jobs` threads.
TargetPrograms scheduleTarget(const ResolvedCatalog& catalog, const Contract& contract, Target target,
                              std::vector<std::pair<std::size_t, std::size_t>> programs, ValidationCache& cache,
                              int jobs);

// `validate(i, groupRun)`: program i's result; groupRun is true for the first run of a
// group (it may use what it shares with the group, e.g. parses) and false for a program
// that runs on its own because its group's result had messages.
using TargetValidate = std::function<ValidatedVariant(std::size_t program, bool groupRun)>;
using TargetKeep = std::function<void(std::size_t program, const ValidatedVariant& result)>;

// Runs the first runs on `jobs` threads, gives every program its result through `keep`
// (in program order), stores the new clean results in the cache and writes its pack.
// Returns the diagnostics in program order. Initialises and finalises glslang.
std::vector<Diagnostic> runTarget(TargetPrograms& scheduled, int jobs, const TargetValidate& validate,
                                  const TargetKeep& keep);

}  // namespace prism::shaderc
