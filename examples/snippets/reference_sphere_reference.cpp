// The usage example of prism/reference/sphere_reference.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/reference/sphere_reference.hpp"
// [/snippet]

#include <cmath>

int main() {
    // [snippet]
    prism::reference::SphereScene scene;  // unit sphere at the origin, view::Camera's default eye on +Z
    scene.lights.directional.push_back({.direction = {0, 0, -1}, .color = {1, 1, 1}});  // head-on
    scene.width = scene.height = 65;
    prism::reference::SphereReference exact = prism::reference::renderSphereReference(scene, true);
    // exact.image: RGBA8, row 0 on top, alpha 255 where the ray hits the sphere, 0 elsewhere
    // exact.radiance: the unclamped colour per pixel, in double
    // [/snippet]
    // The centre ray hits the sphere head-on: ambient 0.1 * 0.8 + lambert 1 * 0.8 + specular
    // 0.5 * 1^32 = 1.38 (view::Material and view::Lights defaults), clamped to 255.
    const std::size_t centre = 32 * 65 + 32;
    const bool hit = exact.covered[centre] == 1 && exact.image.data[centre * 4 + 3] == 255;
    const bool missedCorner = exact.covered[0] == 0 && exact.image.data[3] == 0;
    const bool value = std::abs(exact.radiance[centre].r - 1.38) < 1e-3 && exact.image.data[centre * 4] == 255;
    return hit && missedCorner && value && exact.clampedPixels > 0 ? 0 : 1;
}
