// Writing the flattened stages for --emit-glsl (see glsl_emitter.hpp).
#include "glsl_emitter.hpp"

#include "output_file.hpp"

namespace prism::shaderc {

bool emitGlsl(const std::string& dir, const CatalogData& catalog, std::string& error) {
    for (const auto& s : catalog.shaders) {
        for (const auto& v : s.variants) {
            std::string base = dir + "/" + s.name;
            if (s.variants.size() > 1 || !v.defines.empty()) {
                std::string suffix;
                for (const auto& [n, val] : v.defines) suffix += (suffix.empty() ? "" : "_") + n + "-" + val;
                base += "." + suffix;
            }
            for (const auto& st : v.stages)
                if (writeIfChanged(base + "." + std::string(catalog::stageName(st.stage)), st.text, error) ==
                    WriteOutcome::Failed)
                    return false;
        }
    }
    return true;
}

}  // namespace prism::shaderc
