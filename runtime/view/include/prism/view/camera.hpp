// A perspective camera with look-at, validated so extreme inputs give a clear error
// instead of NaN matrices.
//
// Usage (snippet: examples/snippets/view_camera.cpp):
//
//     #include "prism/view/camera.hpp"
//     prism::view::Camera cam{.eye = {0, 0, 3}, .target = {0, 0, 0}};
//     glm::mat4 view = cam.view();                  // world -> eye
//     glm::mat4 proj = cam.projection(16.f / 9.f);  // eye -> clip
//
// view() picks another up axis when `up` is parallel to the viewing direction, so a
// camera looking straight down still works. projection() throws std::invalid_argument
// for a non-positive near plane, far <= near, a field of view outside (0, 180) degrees
// or non-finite values. Near/far ratios up to 1e9 are allowed (depth precision falls).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace prism::view {

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 3.0f};
    glm::vec3 target{0.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

}  // namespace prism::view
