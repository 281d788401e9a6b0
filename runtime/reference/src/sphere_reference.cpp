// The exact-sphere reference image (see prism/reference/sphere_reference.hpp):
// ray casting against the analytic sphere and modules/lighting.glsl in double.
#include "prism/reference/sphere_reference.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prism::reference {
namespace {

constexpr double kEpsilon = 1e-20;  // PRISM_EPSILON of modules/math_utils.glsl

glm::dvec3 safeNormalize(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len2 = glm::dot(v, v);
    return (len2 > kEpsilon && len2 < 3.0e38) ? v / std::sqrt(len2) : fallback;
}

double safePow(double x, double y) {
    const double e = std::max(y, 1e-6);
    return x > 0.0 ? std::pow(x, e) : 0.0;
}

// GLSL reflect(I, N) = I - 2 dot(N, I) N.
glm::dvec3 reflect(const glm::dvec3& i, const glm::dvec3& n) {
    return i - 2.0 * glm::dot(n, i) * n;
}

double phongSpecular(const glm::dvec3& toLight, const glm::dvec3& toEye, const glm::dvec3& normal, double shininess) {
    return safePow(std::max(glm::dot(reflect(-toLight, normal), toEye), 0.0), shininess);
}

// view::Camera::view() in double: the same look-at and the same fallback up axis.
glm::dmat4 viewMatrix(const view::Camera& camera) {
    const glm::dvec3 eye(camera.eye), target(camera.target), up(camera.up);
    glm::dvec3 forward = target - eye;
    if (glm::dot(forward, forward) < 1e-24) throw std::invalid_argument("sphere reference: eye and target coincide");
    forward = glm::normalize(forward);
    glm::dvec3 upAxis = glm::dot(up, up) > 1e-24 ? glm::normalize(up) : glm::dvec3(0, 1, 0);
    if (std::abs(glm::dot(forward, upAxis)) > 0.9999)
        upAxis = std::abs(forward.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    return glm::lookAt(eye, eye + forward, upAxis);
}

glm::dvec3 lightContribution(const glm::dvec3& toLight, const glm::dvec3& radiance, const glm::dvec3& toEye,
                             const glm::dvec3& normal, const view::Material& m, bool withSpecular) {
    const double lambert = glm::dot(normal, toLight);
    if (lambert <= 0.0) return glm::dvec3(0.0);
    glm::dvec3 c = glm::dvec3(m.color) * lambert;
    if (withSpecular) c += static_cast<double>(m.specular) * phongSpecular(toLight, toEye, normal, m.shininess);
    return c * radiance;
}

}  // namespace

std::uint8_t toUnorm8(double value) {
    if (std::isnan(value)) value = 0.0;
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}

glm::dvec3 shadeEyeSpace(const glm::dvec3& eyePosition, const glm::dvec3& normal, const SphereScene& scene,
                         bool withSpecular) {
    const glm::dmat4 view = viewMatrix(scene.camera);
    const glm::dmat3 rotation(view);
    const view::Material& m = scene.material;
    const glm::dvec3 toEye = safeNormalize(-eyePosition, glm::dvec3(0, 0, 1));
    glm::dvec3 color = glm::dvec3(scene.lights.ambient) * glm::dvec3(m.color);
    for (const auto& l : scene.lights.directional) {
        const glm::dvec3 toLight = safeNormalize(rotation * -glm::dvec3(l.direction), glm::dvec3(0, 0, 1));
        color += lightContribution(toLight, glm::dvec3(l.color), toEye, normal, m, withSpecular);
    }
    for (const auto& l : scene.lights.points) {
        const glm::dvec3 lightEye = glm::dvec3(view * glm::dvec4(glm::dvec3(l.position), 1.0));
        const glm::dvec3 toLight = safeNormalize(lightEye - eyePosition, normal);
        color += lightContribution(toLight, glm::dvec3(l.color), toEye, normal, m, withSpecular);
    }
    return color;
}

SphereReference renderSphereReference(const SphereScene& scene, bool withSpecular) {
    if (scene.width <= 0 || scene.height <= 0) throw std::invalid_argument("sphere reference: empty image");
    const view::Camera& cam = scene.camera;
    const glm::dmat4 view = viewMatrix(cam);
    const glm::dvec3 centre = glm::dvec3(view * glm::dvec4(scene.centre, 1.0));  // eye space
    const double r = scene.radius;
    const double aspect = static_cast<double>(scene.width) / static_cast<double>(scene.height);
    const double tanHalf = std::tan(static_cast<double>(cam.fovYDegrees) * M_PI / 360.0);

    SphereReference out;
    out.width = scene.width;
    out.height = scene.height;
    out.radiance.assign(static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height),
                        scene.background);
    out.covered.assign(out.radiance.size(), 0);
    out.image =
        image::Image8(scene.width, scene.height,
                      {toUnorm8(scene.background.r), toUnorm8(scene.background.g), toUnorm8(scene.background.b), 0});

    for (int y = 0; y < scene.height; ++y) {
        const double ndcY = 1.0 - 2.0 * (y + 0.5) / scene.height;
        for (int x = 0; x < scene.width; ++x) {
            const double ndcX = 2.0 * (x + 0.5) / scene.width - 1.0;
            const glm::dvec3 dir = glm::normalize(glm::dvec3(ndcX * aspect * tanHalf, ndcY * tanHalf, -1.0));
            // |t d - c|^2 = r^2 with |d| = 1: t = d.c -+ sqrt((d.c)^2 - |c|^2 + r^2).
            const double b = glm::dot(dir, centre);
            const double disc = b * b - glm::dot(centre, centre) + r * r;
            if (disc < 0.0) continue;
            const double t = b - std::sqrt(disc);  // the front hit
            const glm::dvec3 p = t * dir;
            if (-p.z < cam.nearPlane)
                throw std::invalid_argument("sphere reference: the near plane cuts the sphere; move the camera back");
            if (-p.z > cam.farPlane) continue;
            const glm::dvec3 n = (p - centre) / r;
            const glm::dvec3 c = shadeEyeSpace(p, n, scene, withSpecular);
            const std::size_t i =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(scene.width) + static_cast<std::size_t>(x);
            out.radiance[i] = c;
            out.covered[i] = 1;
            if (c.r > 1.0 || c.g > 1.0 || c.b > 1.0) ++out.clampedPixels;
            out.image.set(x, y, {toUnorm8(c.r), toUnorm8(c.g), toUnorm8(c.b), 255});
        }
    }
    return out;
}

}  // namespace prism::reference
