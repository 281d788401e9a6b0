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
    const SoftShadowShaderInputs in = softShadowShaderInputs(scene);
    // Every uniform of soft_shadows.frag, as a list of components; samplers name texture units.
    const Json uniforms = {{"u_frame", {options.frame}},
                           {"u_spp", {options.spp}},
                           {"u_imageSize", {options.width, options.height}},
                           {"u_extent", {in.extent}},
                           {"u_light", in.light},
                           {"u_sphere0", in.spheres[0]},
                           {"u_sphere1", in.spheres[1]},
                           {"u_sphere2", in.spheres[2]},
                           {"u_blueNoiseSampler", {static_cast<int>(options.sampler)}},
                           {"u_blueNoiseMask", {0}},
                           {"u_blueNoiseSeeds", {1}},
                           {"u_blueNoiseStack", {2}},
                           {"u_blueNoiseStackDepth", {setup.tables.stackDepth}}};
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
