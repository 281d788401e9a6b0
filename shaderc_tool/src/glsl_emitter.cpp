// The flattened stages for --emit-glsl and their SPIR-V for --emit-spirv, as files (see glsl_emitter.hpp).
#include "glsl_emitter.hpp"

#include "es300_target.hpp"

namespace prism::shaderc {
namespace {

// DIR/<shader>[.<variant>]: the start of every file name of one variant's stages.
std::string variantBase(const std::string& dir, const CatalogShader& s, const CatalogVariant& v) {
    std::string base = dir + "/" + s.name;
    if (s.variants.size() > 1 || !v.defines.empty()) {
        std::string suffix;
        for (const auto& [n, val] : v.defines) suffix += (suffix.empty() ? "" : "_") + n + "-" + val;
        base += "." + suffix;
    }
    return base;
}

std::string stagePath(const std::string& base, catalog::Stage stage) {
    return base + "." + std::string(catalog::stageName(stage));
}

}  // namespace

std::string spirvFileName(const CatalogShader& s, const CatalogVariant& v, catalog::Stage stage) {
    return stagePath(variantBase("", s, v), stage).substr(1) + ".spv";
}

std::vector<GeneratedFile> glslFiles(const std::string& dir, const CatalogData& catalog,
                                     const std::vector<Target>& runTargets,
                                     const std::vector<std::vector<Target>>& targets) {
    std::vector<GeneratedFile> files;
    const bool nameTargets = runTargets != std::vector<Target>{Target::Gl};
    for (std::size_t i = 0; i < catalog.shaders.size(); ++i) {
        const auto& s = catalog.shaders[i];
        for (const auto& v : s.variants)
            for (const Target t : targets[i]) {
                if (t == Target::Spirv) continue;  // words, not text: --emit-spirv
                const std::string base =
                    variantBase(dir, s, v) + (nameTargets ? "." + std::string(targetName(t)) : std::string());
                for (const auto& st : v.stages)
                    files.push_back({stagePath(base, st.stage), t == Target::Es300 ? es300Text(st.text) : st.text});
            }
    }
    return files;
}

std::vector<GeneratedFile> spirvFiles(const std::string& dir, const CatalogData& catalog) {
    std::vector<GeneratedFile> files;
    for (const auto& s : catalog.shaders)
        for (const auto& v : s.variants) {
            if (!v.spirv) continue;
            for (const auto& st : v.spirv->spirv) {
                std::string bytes(st.words.size() * sizeof(std::uint32_t), '\0');
                for (std::size_t i = 0; i < st.words.size(); ++i)
                    for (std::size_t b = 0; b < 4; ++b)
                        bytes[4 * i + b] = static_cast<char>((st.words[i] >> (8 * b)) & 0xFF);
                files.push_back({dir + "/" + spirvFileName(s, v, st.stage), std::move(bytes)});
            }
        }
    return files;
}

}  // namespace prism::shaderc
