// The live view's record of one soft-shadow render (live_record.hpp).
#include "live_record.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace prism::bluenoise::app {

void writeLiveRecord(const std::string& path, const std::string& png, const SoftShadowScene& scene,
                     const StochasticSetup& setup, const RenderOptions& options) {
    using Json = nlohmann::ordered_json;
    const SoftShadowUniforms u = softShadowUniforms(scene, setup.tables, options);
    // Every uniform of soft_shadows.frag, as a list of components; samplers name texture units.
    const Json uniforms = {{"u_frame", {options.frame}},
                           {"u_spp", {u.spp}},
                           {"u_imageSize", u.imageSize},
                           {"u_extent", {u.extent}},
                           {"u_light", u.light},
                           {"u_sphere0", u.spheres[0]},
                           {"u_sphere1", u.spheres[1]},
                           {"u_sphere2", u.spheres[2]},
                           {"u_blueNoiseSampler", {u.sampler}},
                           {"u_blueNoiseMask", {0}},
                           {"u_blueNoiseSeeds", {1}},
                           {"u_blueNoiseStack", {2}},
                           {"u_blueNoiseStackDepth", {u.stackDepth}}};
    const Json record = {
        {"png", std::filesystem::path(png).filename().string()},
        {"width", options.width},
        {"height", options.height},
        {"uniforms", uniforms},
        {"mask",
         {{"width", setup.tables.maskWidth}, {"height", setup.tables.maskHeight}, {"values", setup.tables.mask}}}};
    std::ofstream out(path);
    out << record.dump() << "\n";
    if (!out.flush()) throw std::runtime_error("prism-bluenoise: cannot write " + path);
}

}  // namespace prism::bluenoise::app
