// A Monte Carlo effect to show the samplers: soft shadows of spheres on a ground plane
// under a rectangular area light, seen from straight above, rendered on the CPU.
//
// Usage (snippet: examples/snippets/bluenoise_soft_shadows.cpp):
//
//     #include "prism/bluenoise/soft_shadows.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     namespace bn = prism::bluenoise;
//     bn::SoftShadowScene scene = bn::SoftShadowScene::classic();
//     bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
//     bn::RenderOptions options;
//     options.width = options.height = 32;
//     options.sampler = bn::SamplerKind::BlueNoise;
//     bn::RealImage image = bn::renderSoftShadows(scene, setup, options);  // 1 spp, frame 0
//     bn::Reference reference = bn::renderReference(scene, 32, 32, 1024);
//     bn::ErrorStats error = bn::compareToReference(image, reference);
//
// Pixel (x, y) sees the ground point ((x + 0.5) / W * 2e - e, e - (y + 0.5) / H * 2e), e =
// scene.extent. Its value is the light's irradiance there, sum of V(p, q) L cos cos / r^2
// over light points q, relative to the unoccluded irradiance below the light's centre
// (not clamped: a clamp per frame would bias the accumulated mean; clamp for display).
// Sample i of frame t uses sampler frame t * spp + i, dimension 0 along the light's long side and dimension 1 across.
// The sorted sampler runs the temporal pipeline of Heitz & Belcour (sorting.hpp): after
// each frame t the seeds are sorted in blocks against the mask shifted by t times the R2
// frame step (thesis Algorithm 6) and retargeted towards frame t+1's shift (retarget.hpp);
// with `aPosteriori` every frame is instead rendered, sorted and rendered again (the
// sorting pass alone on a static scene).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "prism/bluenoise/mask.hpp"
#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/samplers.hpp"

namespace prism::bluenoise {

struct Sphere {
    double x, y, z, radius;
};

struct SoftShadowScene {
    double extent = 1.5;           // ground square half-size
    double lightHeight = 2.0;      // light centre (0, 0, lightHeight), facing down
    double lightHalfLength = 0.8;  // along x
    double lightHalfWidth = 0.01;  // along y: a strip light (a fluorescent tube)
    double radiance = 1.0;         // relative: 1 gives 1.0 right below the light
    std::vector<Sphere> spheres;

    static SoftShadowScene classic();  // three spheres at different heights
    static SoftShadowScene black();    // light off: every pixel 0
    static SoftShadowScene white();    // no occluder, a light far brighter than 1: white on display
};

struct StochasticSetup {
    Mask mask;
    SamplerTables tables;          // mask values; seeds are filled per render
    RetargetPermutation retarget;  // empty: no retargeting
    int shiftX = 0, shiftY = 0;    // R2 step between frames

    static StochasticSetup make(const Mask& mask);
};

struct RenderOptions {
    int width = 128, height = 128;
    int spp = 1;
    SamplerKind sampler = SamplerKind::White;
    int frame = 0;             // the frame rendered (frames == 1)
    int frames = 1;            // > 1: the mean of frames 0 .. frames-1
    int block = 8;             // sorting block size
    bool aPosteriori = false;  // sorted: render, sort, render again each frame
    std::uint64_t seed = 1;    // the sorted sampler's first seeds
};

RealImage renderSoftShadows(const SoftShadowScene& scene, StochasticSetup& setup, const RenderOptions& options);

// The frame loop of renderSoftShadows (accumulation, sorting, retargeting) around any
// frame renderer: `renderFrame(tables, frame)` returns width*height values, row 0 at the
// top (the GPU version, gl_soft_shadows.hpp, reads its framebuffer back).
using FrameRenderer = std::function<std::vector<double>(const SamplerTables& tables, std::uint32_t frame)>;
RealImage runSoftShadowPipeline(StochasticSetup& setup, const RenderOptions& options, const FrameRenderer& renderFrame);

// Irradiance scale of the scene: radiance / the unoccluded irradiance below the light.
double irradianceScale(const SoftShadowScene& scene);

// The GPU version's uniforms (shader_sources/bluenoise/soft_shadows.frag) but u_frame, as
// the GL and the Vulkan frame renderers both set them and `prism-bluenoise render
// --live-record` writes them for the report's live view (docs/web.md): all three draw the
// same scene. Throws std::invalid_argument for more
// than kGpuSpheres spheres.
inline constexpr std::size_t kGpuSpheres = 3;
struct SoftShadowUniforms {
    int stackDepth = 1;                                       // u_blueNoiseStackDepth
    int sampler = 0;                                          // u_blueNoiseSampler (SamplerKind)
    int spp = 1;                                              // u_spp
    std::array<float, 2> imageSize{};                         // u_imageSize
    float extent = 0.0f;                                      // u_extent
    std::array<float, 4> light{};                             // u_light: height, half-length, half-width, scale
    std::array<std::array<float, 4>, kGpuSpheres> spheres{};  // u_sphere0..2: centre, radius (0: none)
};
SoftShadowUniforms softShadowUniforms(const SoftShadowScene& scene, const SamplerTables& tables,
                                      const RenderOptions& options);

struct Reference {
    RealImage image;
    std::vector<char> touched;  // penumbrae: pixels that see part of the light
};

// About `samples` jittered-stratified samples per pixel on a grid of strata shaped like
// the light (1024 on the classic light: 128 x 8), independent of the three samplers.
Reference renderReference(const SoftShadowScene& scene, int width, int height, int samples);

struct ErrorStats {
    double rms = 0.0;                // over touched pixels
    double blurredRms = 0.0;         // of the error blurred by a Gaussian, sigma 1 px
    double lowFrequencyRatio = 0.0;  // of the error image
    int pixels = 0;                  // touched pixels
};

ErrorStats compareToReference(const RealImage& image, const Reference& reference);

}  // namespace prism::bluenoise
