// The rain catalogue's program cache with a usage record (see prism/rain/rain_programs.hpp).
#include "prism/rain/rain_programs.hpp"

#include "prism/rain_shaders.hpp"

namespace prism::rain {

const catalog::Catalog& rainCatalog() {
    return rain_shaders::kCatalog;
}

RainPrograms::RainPrograms() : cache_(rain_shaders::kCatalog) {}

gl::Program& RainPrograms::get(std::string_view shader, const render::VariantValues& variant) {
    gl::Program& p = cache_.get(shader, variant);
    used_.insert(std::string(shader) + " (" + std::string(cache_.variantOf(shader, variant).name) + ")");
    return p;
}

}  // namespace prism::rain
