// Uploading the rain system's procedural R8 texture arrays (streaks, fog noise). Internal
// to prism_rain.
#pragma once

#include <cstdint>

#include "prism/gl/handles.hpp"

namespace prism::rain {

// An R8 2D texture array of `layers` layers of width x height texels, linearly filtered,
// clamped or repeated; throws gl::GlError when GL rejects it.
gl::Texture uploadR8TextureArray(int width, int height, int layers, const std::uint8_t* texels, bool repeat);

}  // namespace prism::rain
