// The in-memory catalogue the pipeline assembles and the header and data writers print: every
// shader with its validated variants, every module, and the binding contract.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "contract.hpp"
#include "reflection.hpp"
#include "spirv_env.hpp"
#include "target_rules.hpp"
#include "shown_path.hpp"
#include "variants.hpp"

namespace prism::shaderc {

struct CatalogStage {
    catalog::Stage stage;
    std::string text;                 // flattened, driver-safe GLSL
    std::vector<EmbeddedPath> files;  // index = source number; paths as embedded
};

struct CatalogVariant {
    std::string name;
    std::vector<std::pair<std::string, std::string>> defines;
    std::vector<CatalogStage> stages;
    ProgramReflection reflection;
    bool es300 = false;  // the es300 target was produced for it (es300_target.hpp)
    // The variant's SPIR-V and its layout, the one place every output reads them: the spirv
    // target's, or a Vulkan-client catalogue's own (its `reflection`), both filled by stage 5's
    // buildSpirvTarget (spirv_target.hpp); empty when the run made none for it. The spirv
    // target's `attributes` are the vertex inputs at the locations glslang assigned.
    std::optional<ProgramReflection> spirv = {};
};

// The words of `stage` in `r`, or nullptr.
inline const std::vector<std::uint32_t>* stageWords(const ProgramReflection& r, catalog::Stage stage) {
    for (const auto& s : r.spirv)
        if (s.stage == stage) return &s.words;
    return nullptr;
}

struct CatalogShader {
    std::string name;
    std::vector<Axis> axes;
    std::vector<CatalogVariant> variants;
    std::vector<std::uint32_t> modules;  // indices into CatalogData::modules, sorted
};

struct CatalogModule {
    std::string identifier;  // ModuleId enumerator, e.g. "lights" or "lighting_phong"
    std::string path;        // as embedded
    std::string description;
    std::string text;                         // own text, #include/#pragma once blanked
    std::vector<std::uint32_t> dependencies;  // direct includes, in order
    std::string sourcePath;                   // as read (for the depfile), not embedded
    std::uint32_t searchDir = 0;              // what `path` is relative to (EmbeddedPath)
};

struct CatalogData {
    std::string nameSpace;
    std::string fingerprint;   // of every input; lets an unchanged run skip validation
    std::string sourcesBlock;  // closing comment: the files read and their fingerprint (source_fingerprint.hpp)
    std::string versionDirective;
    TargetRules rules;                   // the client's (Options::rules); with a spirvEnv, SPIR-V is stored
    std::vector<CatalogShader> shaders;  // sorted by name
    std::vector<CatalogModule> modules;  // sorted by identifier
    Contract contract;
    std::vector<EmbeddedPath> contractFiles;  // contract.files as embedded, for run-time contract errors
};

}  // namespace prism::shaderc
