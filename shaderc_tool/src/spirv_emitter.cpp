// Writing the spirv target's .spv files for --emit-spirv (see spirv_emitter.hpp).
#include "spirv_emitter.hpp"

#include "glsl_emitter.hpp"
#include "output_file.hpp"

namespace prism::shaderc {

bool emitSpirv(const std::string& dir, const CatalogData& catalog, std::string& error) {
    for (const auto& s : catalog.shaders)
        for (const auto& v : s.variants) {
            if (!v.spirv) continue;
            for (const auto& st : v.spirv->stages) {
                const std::string bytes(reinterpret_cast<const char*>(st.words.data()),
                                        st.words.size() * sizeof(std::uint32_t));
                const auto path =
                    emittedVariantBase(dir, s, v) + "." + std::string(catalog::stageName(st.stage)) + ".spv";
                if (writeIfChanged(path, bytes, error) == WriteOutcome::Failed) return false;
            }
        }
    return true;
}

}  // namespace prism::shaderc
