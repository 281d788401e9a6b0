// The Monte Carlo effect of a scene's "stochastic" settings (docs/scenes.md), rendered on
// the CPU with prism_bluenoise_core: soft shadows from an area light with white,
// blue-noise or sorted samples (docs/bluenoise.md). Deterministic: the same settings give
// the same image on every machine run.
//
// Usage (snippet: examples/snippets/scene_stochastic.cpp):
//
//     #include "prism/scene/stochastic.hpp"
//     prism::scene::Scene scene = prism::scene::loadScene("examples/scenes/soft_shadows.json");
//     scene.stochastic->sampler = prism::bluenoise::SamplerKind::Sorted;
//     prism::image::Image8 image = prism::scene::renderStochastic(*scene.stochastic, scene.width, scene.height);
#pragma once

#include <optional>
#include <string>

#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/image/image.hpp"
#include "prism/scene/scene.hpp"

namespace prism::scene {

inline constexpr unsigned kMaxStochasticSpp = 1024;
inline constexpr unsigned kMaxStochasticFrame = 1000000;
inline constexpr unsigned kMaxStochasticFrames = 1024;
// The sorted sampler replays every frame before the one asked for.
inline constexpr unsigned kMaxSortedFrame = 100000;

// "white", "bluenoise" or "sorted"; nullopt for anything else.
std::optional<bluenoise::SamplerKind> parseStochasticSampler(const std::string& name);
const char* stochasticSamplerName(bluenoise::SamplerKind kind);

// The settings checked and turned into what a frame renderer runs: the mask and sampler
// tables (retargeted for the sorted sampler's later frames) and the render options. Throws
// std::invalid_argument for settings out of range. The CPU render below and the Vulkan one
// (prism/scene/vulkan_scene.hpp) both start here.
struct StochasticRun {
    bluenoise::StochasticSetup setup;
    bluenoise::RenderOptions options;
};
StochasticRun prepareStochastic(const StochasticSettings& settings, int width, int height);

// The irradiance estimate, width x height values, not clamped (for metrics and means).
bluenoise::RealImage renderStochasticValues(const StochasticSettings& settings, int width, int height);
// An estimate as an opaque grey image, clamped to [0, 1] (NaN and Inf as 0).
image::Image8 toGreyImage(const bluenoise::RealImage& values);
// The same as an opaque grey image, clamped to [0, 1]. Throws std::invalid_argument for
// settings out of range (e.g. a sorted frame past kMaxSortedFrame).
image::Image8 renderStochastic(const StochasticSettings& settings, int width, int height);

}  // namespace prism::scene
