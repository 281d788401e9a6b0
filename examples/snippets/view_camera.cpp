// The usage example of prism/view/camera.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/view/camera.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::view::Camera cam{.eye = {0, 0, 3}, .target = {0, 0, 0}};
    glm::mat4 view = cam.view();                  // world -> eye
    glm::mat4 proj = cam.projection(16.f / 9.f);  // eye -> clip
    // [/snippet]
    return view[3][2] == -3.0f && std::isfinite(proj[0][0]) ? 0 : 1;
}
