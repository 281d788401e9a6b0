// The soft-shadow demo on the GPU (shader_sources/bluenoise/soft_shadows.*, using
// modules/bluenoise/sampling.glsl), with the CPU frame loop of soft_shadows.hpp around it.
//
// Usage (snippet: examples/snippets/bluenoise_gl_soft_shadows.cpp; needs a current GL 3.3 context):
//
//     #include "prism/bluenoise/gl_soft_shadows.hpp"
//     #include "prism/bluenoise/void_and_cluster.hpp"
//     #include "prism/gl/gl_context.hpp"
//     namespace bn = prism::bluenoise;
//     auto context = prism::gl::createContext();
//     bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
//     bn::RenderOptions options;
//     options.width = options.height = 32;
//     options.sampler = bn::SamplerKind::BlueNoise;
//     bn::GlSoftShadows gpu(32, 32);
//     bn::RealImage image = gpu.render(bn::SoftShadowScene::classic(), setup, options);
//     double ms = gpu.lastFrameMilliseconds();  // GPU draw + readback of the last frame
//
// The mask, seeds and stack go to R32UI textures (units 0, 1 and 2), the frame is drawn into an
// RGBA32F framebuffer and read back; the sorted sampler's sorting and retargeting run on
// the CPU between frames, as in renderSoftShadows. Up to 3 spheres (more throw; softShadowUniforms).
#pragma once

#include <memory>

#include "prism/bluenoise/soft_shadows.hpp"

namespace prism::bluenoise {

class GlSoftShadows {
  public:
    GlSoftShadows(int width, int height);
    ~GlSoftShadows();
    GlSoftShadows(const GlSoftShadows&) = delete;
    GlSoftShadows& operator=(const GlSoftShadows&) = delete;

    RealImage render(const SoftShadowScene& scene, StochasticSetup& setup, const RenderOptions& options);
    double lastFrameMilliseconds() const { return lastMs_; }

  private:
    struct Resources;
    std::unique_ptr<Resources> gl_;
    double lastMs_ = 0.0;
};

}  // namespace prism::bluenoise
