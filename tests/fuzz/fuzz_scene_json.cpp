// libFuzzer harness: scene JSON to a validated prism::scene::Scene (no GL is touched).
// Oracle: every bad scene is a SceneError (no other exception escapes), no crash,
// leak or undefined behaviour; an accepted scene holds only finite, in-range values.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.hpp"
#include "prism/scene/scene_loader.hpp"

namespace {

void require(bool condition, const char* what) {
    if (!condition) {
        std::fprintf(stderr, "accepted scene breaks: %s\n", what);
        std::abort();
    }
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    prism::scene::Scene scene;
    try {
        scene = prism::scene::parseScene(prism::fuzz::text(data, size), "fuzz.json");
    } catch (const prism::scene::SceneError&) {
        return 0;
    }
    require(scene.width >= 1 && scene.height >= 1, "image size");
    require(finite(scene.camera.eye) && finite(scene.camera.target), "camera");
    require(scene.camera.farPlane > scene.camera.nearPlane, "near/far");
    for (const auto& d : scene.lights.directional) require(finite(d.direction) && finite(d.color), "directional light");
    for (const auto& p : scene.lights.points) require(finite(p.position) && finite(p.color), "point light");
    if (scene.rain) require(!scene.rain->particleBudget || *scene.rain->particleBudget <= (1u << 24), "rain budget");
    if (scene.water) require(scene.water->gridSize >= 1 && scene.water->gridSize <= 2048, "water grid");
    return 0;
}
