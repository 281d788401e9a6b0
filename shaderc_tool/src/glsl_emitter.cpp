// Writing the flattened stages for --emit-glsl (see glsl_emitter.hpp).
#include "glsl_emitter.hpp"

#include "es300_target.hpp"
#include "output_file.hpp"

namespace prism::shaderc {

std::string emittedVariantBase(const std::string& dir, const CatalogShader& s, const CatalogVariant& v) {
    std::string base = dir + "/" + s.name;
    if (s.variants.size() > 1 || !v.defines.empty()) {
        std::string suffix;
        for (const auto& [n, val] : v.defines) suffix += (suffix.empty() ? "" : "_") + n + "-" + val;
        base += "." + suffix;
    }
    return base;
}

bool emitGlsl(const std::string& dir, const CatalogData& catalog, const std::vector<Target>& runTargets,
              const std::vector<std::vector<Target>>& targets, std::string& error) {
    const bool nameTargets = runTargets != std::vector<Target>{Target::Gl};
    for (std::size_t i = 0; i < catalog.shaders.size(); ++i) {
        const auto& s = catalog.shaders[i];
        for (const auto& v : s.variants)
            for (const Target t : targets[i]) {
                if (t == Target::Spirv) continue;  // words, not text
                const std::string base =
                    emittedVariantBase(dir, s, v) + (nameTargets ? "." + std::string(targetName(t)) : std::string());
                for (const auto& st : v.stages) {
                    const std::string text = t == Target::Es300 ? es300Text(st.text) : st.text;
                    if (writeIfChanged(base + "." + std::string(catalog::stageName(st.stage)), text, error) ==
                        WriteOutcome::Failed)
                        return false;
                }
            }
    }
    return true;
}

}  // namespace prism::shaderc
