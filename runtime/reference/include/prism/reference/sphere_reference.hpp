// The ground truth of the speed/accuracy measurements (prism_bench_tradeoffs,
// docs/tradeoffs.md, and the viewer's error readout): the EXACT sphere lit per pixel on
// the CPU in double precision, with the formula of modules/lighting.glsl, so a rendered
// icosphere can be compared with what the mesh only approximates.
//
// Usage (snippet: examples/snippets/reference_sphere_reference.cpp):
//
//     #include "prism/reference/sphere_reference.hpp"
//     prism::reference::SphereScene scene;  // unit sphere at the origin, view::Camera's default eye on +Z
//     scene.lights.directional.push_back({.direction = {0, 0, -1}, .color = {1, 1, 1}});  // head-on
//     scene.width = scene.height = 65;
//     prism::reference::SphereReference exact = prism::reference::renderSphereReference(scene, true);
//     // exact.image: RGBA8, row 0 on top, alpha 255 where the ray hits the sphere, 0 elsewhere
//     // exact.radiance: the unclamped colour per pixel, in double
//
// Method, per pixel (x, y) of a width x height image (row 0 = top):
//  * The ray starts at the eye and goes through the pixel CENTRE, where the rasteriser
//    samples: NDC (2(x+0.5)/w - 1, 1 - 2(y+0.5)/h), eye-space direction
//    (ndc.x * aspect * tan(fovY/2), ndc.y * tan(fovY/2), -1), i.e. exactly the inverse of
//    view::Camera::projection(). The view matrix is view::Camera::view() rebuilt in double (same
//    look-at, same fallback up axis).
//  * It is intersected with the analytic sphere (centre, radius; world space, the world
//    matrix being translate(centre) * scale(radius) applied to a unit sphere) moved to
//    eye space; the front hit counts (beyond the far plane: background; a near plane
//    that cuts the sphere throws std::invalid_argument). No hit: the background colour.
//  * At the hit point p (eye space) the normal is the exact (p - c_eye) / r, and the
//    colour is shade(p, n) of modules/lighting.glsl, term by term:
//        ambient * albedo
//      + sum over lights with lambert = dot(n, L) > 0 of
//            (albedo * lambert + specular * phongSpecular(L, E, n, shininess)) * lightColour
//    with E = safeNormalize(-p, (0,0,1)), directional L = safeNormalize(mat3(view) *
//    -direction, (0,0,1)), point L = safeNormalize(view * position - p, n),
//    phongSpecular = safePow(max(dot(reflect(-L, n), E), 0), shininess) and safePow(x, y) =
//    x > 0 ? x^max(y, 1e-6) : 0 (modules/math_utils.glsl and modules/specular.glsl).
//    `withSpecular = false` drops the specular term (the flat and smooth shaders'
//    model). Only the Phong (reflection) specular is modelled, not BLINN.
//  * 8 bits as a UNORM8 framebuffer stores it: clamp to [0, 1], then round to nearest
//    (x * 255), as GL's float-to-unorm conversion and prism::image::toImage8 do; the
//    background goes through the same conversion.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

#include "prism/view/camera.hpp"
#include "prism/image/image.hpp"
#include "prism/view/lighting.hpp"

namespace prism::reference {

struct SphereScene {
    view::Camera camera;
    view::Lights lights;
    view::Material material;
    glm::dvec3 centre{0.0};  // world space
    double radius = 1.0;
    int width = 512;
    int height = 512;
    glm::dvec3 background{0.05, 0.06, 0.08};
};

struct SphereReference {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> radiance;   // unclamped shade() per pixel (background where missed)
    std::vector<std::uint8_t> covered;  // 1 where the ray hits the sphere
    image::Image8 image;                // radiance in 8 bits; alpha 255 covered, 0 background
    std::size_t clampedPixels = 0;      // covered pixels with a channel above 1 before clamping
};

// shade() of modules/lighting.glsl in double, for an eye-space point and unit normal.
glm::dvec3 shadeEyeSpace(const glm::dvec3& eyePosition, const glm::dvec3& normal, const SphereScene& scene,
                         bool withSpecular);

SphereReference renderSphereReference(const SphereScene& scene, bool withSpecular);

// A UNORM8 channel as the framebuffer stores `value`: clamp to [0, 1], round to nearest.
std::uint8_t toUnorm8(double value);

}  // namespace prism::reference
