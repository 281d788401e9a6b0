// Uploading the rain system's procedural 8-bit texture arrays (streaks, fog noise). Internal
// to prism_rain.
#pragma once

#include <cstdint>

#include "prism/gl/handles.hpp"

namespace prism::rain {

// An 8-bit unorm 2D texture array (R8 for channels 1, RGBA8 for 4) of `layers` layers of width x height
// texels, linearly filtered, clamped or repeated; throws gl::GlError when GL rejects it.
gl::Texture uploadTextureArray8(int width, int height, int layers, int channels, const std::uint8_t* texels,
                                bool repeat);

}  // namespace prism::rain
