// `prism-bluenoise render --live-record PATH`: what the GPU soft-shadow shader
// (shader_sources/bluenoise/soft_shadows.frag) needs to draw the frame just rendered: its
// uniforms (from softShadowUniforms, the values GlSoftShadows sets) and the blue-noise
// mask as the R32UI texture holds it. scripts/gallery_live.py embeds it in the report, whose
// live blue-noise view draws that exact frame through WebGL2 and compares it with the PNG
// (docs/web.md).
//
//     writeLiveRecord("bluenoise/bluenoise-1.live.json", "bluenoise/bluenoise-1.png", scene, setup, options);
#pragma once

#include <string>

#include "prism/bluenoise/soft_shadows.hpp"

namespace prism::bluenoise::app {

// Throws std::runtime_error when `path` cannot be written.
void writeLiveRecord(const std::string& path, const std::string& png, const SoftShadowScene& scene,
                     const StochasticSetup& setup, const RenderOptions& options);

}  // namespace prism::bluenoise::app
