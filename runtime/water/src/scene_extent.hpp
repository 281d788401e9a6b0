// The size a water scene is framed by: the cameras stand off by multiples of it and the
// sky's fog reaches twice it. Internal to prism_water (water_scene.cpp, water_scene_renderer.cpp).
#pragma once

#include <algorithm>

#include "prism/water/height_field.hpp"

namespace prism::water {

// The terrain's larger side in metres (at least one cell).
inline float sceneExtent(const HeightField& t) {
    return std::max({t.sizeX(), t.sizeZ(), t.cellSize});
}

}  // namespace prism::water
