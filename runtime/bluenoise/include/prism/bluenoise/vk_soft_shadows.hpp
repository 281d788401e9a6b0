// The soft-shadow demo through Vulkan: shader_sources/bluenoise/soft_shadows.* from the
// blue-noise catalogue's SPIR-V, with the CPU frame loop of soft_shadows.hpp around it, as
// GlSoftShadows (gl_soft_shadows.hpp) runs it through GL.
//
// Usage (snippet: examples/snippets/bluenoise_vk_soft_shadows.cpp):
//
//     #include "prism/bluenoise/vk_soft_shadows.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     namespace bn = prism::bluenoise;
//     prism::vk::Device device;
//     bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
//     bn::RenderOptions options;
//     options.width = options.height = 32;
//     options.sampler = bn::SamplerKind::BlueNoise;
//     bn::VulkanSoftShadows gpu(device, 32, 32);
//     bn::RealImage image = gpu.render(bn::SoftShadowScene::classic(), setup, options);
//
// The mask, stack and each frame's seeds are R32_UINT images (nearest), bound at the set and
// binding of the SPIR-V's reflection; the uniforms are set by name in its block. Each frame is
// one full-screen triangle into an RGBA32F target, read back for the CPU loop (accumulation,
// the sorted sampler's sorting and retargeting). The shader reads gl_FragCoord, so the pass
// stores its rows in GL's order (ClipConvention::glRowOrder; prism/vk/clip_convention.hpp).
// Up to 3 spheres (more throw). The device must outlive it.
#pragma once

#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/vk/clip_convention.hpp"
#include "prism/vk/device.hpp"
#include "prism/vk/pipeline.hpp"
#include "prism/vk/render_target.hpp"

namespace prism::bluenoise {

class VulkanSoftShadows {
  public:
    // `clip` is GL's row order; the agreement tests pass {} (Vulkan's rows) to show it matters.
    VulkanSoftShadows(const vk::Device& device, int width, int height, vk::ClipConvention clip = {.glRowOrder = true});

    RealImage render(const SoftShadowScene& scene, StochasticSetup& setup, const RenderOptions& options);

  private:
    const vk::Device* device_;
    vk::ClipConvention clip_;
    vk::RenderTarget target_;
    vk::Pipeline pipeline_;
};

}  // namespace prism::bluenoise
