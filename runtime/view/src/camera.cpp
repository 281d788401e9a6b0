// Camera matrices with input validation (see prism/view/camera.hpp).
#include "prism/view/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace prism::view {
namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

glm::mat4 Camera::view() const {
    if (!finite(eye) || !finite(target) || !finite(up))
        throw std::invalid_argument("camera: eye, target and up must be finite");
    glm::vec3 forward = target - eye;
    if (glm::dot(forward, forward) < 1e-24f)
        throw std::invalid_argument("camera: eye and target coincide; move the target away from the eye");
    forward = glm::normalize(forward);
    glm::vec3 upAxis = glm::dot(up, up) > 1e-24f ? glm::normalize(up) : glm::vec3(0, 1, 0);
    if (std::abs(glm::dot(forward, upAxis)) > 0.9999f)
        upAxis = std::abs(forward.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    return glm::lookAt(eye, eye + forward, upAxis);
}

glm::mat4 Camera::projection(float aspect) const {
    if (!(aspect > 0.0f) || !std::isfinite(aspect))
        throw std::invalid_argument("camera: the aspect ratio must be a positive number");
    if (!(fovYDegrees > 0.0f && fovYDegrees < 180.0f))
        throw std::invalid_argument("camera: the field of view must be between 0 and 180 degrees, got " +
                                    std::to_string(fovYDegrees));
    if (!(nearPlane > 0.0f) || !std::isfinite(nearPlane) || !(farPlane > nearPlane) || !std::isfinite(farPlane))
        throw std::invalid_argument("camera: need 0 < near < far (finite), got near " + std::to_string(nearPlane) +
                                    ", far " + std::to_string(farPlane));
    if (farPlane / nearPlane > 1e9f)
        throw std::invalid_argument("camera: far/near ratio above 1e9 leaves no depth precision; raise near");
    return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
}

}  // namespace prism::view
