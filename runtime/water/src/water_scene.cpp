// The water scene: its description's defaults, the water system it owns, the model
// matrix, and the cameras that frame its terrain (see prism/water/water_scene.hpp).
#include "prism/water/water_scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "scene_extent.hpp"

namespace prism::water {

view::Lights WaterSceneDescription::defaultSun() {
    view::Lights l;
    l.ambient = {0.32f, 0.35f, 0.40f};
    l.directional.push_back({.direction = {-0.45f, -0.55f, 0.70f}, .color = {0.85f, 0.82f, 0.74f}});
    return l;
}

WaterScene::WaterScene(WaterSceneDescription d) : description_(std::move(d)) {
    if (description_.terrain.cellCount() == 0 && description_.terrain.heights.empty())
        description_.terrain = proceduralTerrain();
    validate(description_.terrain, "WaterScene terrain");
    if (description_.permeability.empty()) description_.permeability = proceduralPermeability(description_.terrain);
    if (description_.water)
        water_ = std::make_unique<WaterSystem>(description_.terrain, description_.permeability, description_.params,
                                               description_.backend, description_.rainMmPerHour);
}

void WaterScene::advance(double dt) {
    if (water_) water_->advance(dt);
}

glm::mat4 WaterScene::world() const {
    const HeightField& t = description_.terrain;
    return glm::translate(glm::mat4(1.0f),
                          glm::vec3(-0.5f * t.sizeX(), static_cast<float>(t.origin), -0.5f * t.sizeZ()));
}

namespace {

float meanHeight(const HeightField& t) {
    double s = 0.0;
    for (float h : t.heights) s += h;
    return static_cast<float>(s / static_cast<double>(t.heights.size()));
}

}  // namespace

view::Camera overviewCamera(const HeightField& t) {
    const float e = sceneExtent(t), mid = meanHeight(t);
    view::Camera c;
    c.eye = {0.66f * e, mid + 0.40f * e, 0.84f * e};
    c.target = {0.0f, mid - 0.08f * e, 0.0f};
    c.fovYDegrees = 45.0f;
    c.nearPlane = 0.01f * e;
    c.farPlane = 20.0f * e;
    return c;
}

view::Camera groundCamera(const HeightField& t) {
    const float e = sceneExtent(t), mid = meanHeight(t);
    view::Camera c;
    c.eye = {-0.42f * e, mid + 0.16f * e, 0.40f * e};
    c.target = {0.08f * e, mid - 0.04f * e, -0.05f * e};
    c.fovYDegrees = 50.0f;
    c.nearPlane = 0.005f * e;
    c.farPlane = 20.0f * e;
    return c;
}

}  // namespace prism::water
