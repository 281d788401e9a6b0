// Writing the flattened stages for --emit-glsl and their SPIR-V for --emit-spirv (see glsl_emitter.hpp).
#include "glsl_emitter.hpp"

#include <functional>

#include "output_file.hpp"

namespace prism::shaderc {
namespace {

// Calls `write(path without extension, stage)` for every stage of every variant, with
// the deterministic names both options share; false when a write failed.
bool forEachStage(const std::string& dir, const CatalogData& catalog,
                  const std::function<bool(const std::string&, const CatalogVariant&, const CatalogStage&)>& write) {
    for (const auto& s : catalog.shaders) {
        for (const auto& v : s.variants) {
            std::string base = dir + "/" + s.name;
            if (s.variants.size() > 1 || !v.defines.empty()) {
                std::string suffix;
                for (const auto& [n, val] : v.defines) suffix += (suffix.empty() ? "" : "_") + n + "-" + val;
                base += "." + suffix;
            }
            for (const auto& st : v.stages)
                if (!write(base + "." + std::string(catalog::stageName(st.stage)), v, st)) return false;
        }
    }
    return true;
}

}  // namespace

bool emitGlsl(const std::string& dir, const CatalogData& catalog, std::string& error) {
    return forEachStage(dir, catalog, [&](const std::string& path, const CatalogVariant&, const CatalogStage& st) {
        return writeIfChanged(path, st.text, error) != WriteOutcome::Failed;
    });
}

bool emitSpirv(const std::string& dir, const CatalogData& catalog, std::string& error) {
    return forEachStage(dir, catalog, [&](const std::string& path, const CatalogVariant& v, const CatalogStage& st) {
        for (const auto& s : v.reflection.spirv)
            if (s.stage == st.stage) {
                std::string bytes(s.words.size() * sizeof(std::uint32_t), '\0');
                for (std::size_t i = 0; i < s.words.size(); ++i)
                    for (std::size_t b = 0; b < 4; ++b)
                        bytes[4 * i + b] = static_cast<char>((s.words[i] >> (8 * b)) & 0xFF);
                return writeIfChanged(path + ".spv", bytes, error) != WriteOutcome::Failed;
            }
        return true;
    });
}

}  // namespace prism::shaderc
