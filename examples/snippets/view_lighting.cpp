// The usage example of prism/view/lighting.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/view/lighting.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::view::Lights lights;
    lights.ambient = {0.1f, 0.1f, 0.1f};
    lights.directional.push_back({.direction = {-1, -1, -1}, .color = {1, 1, 1}});
    prism::view::Material m{.color = {0.8f, 0.3f, 0.2f, 1.f}, .shininess = 32.f, .specular = 0.5f};
    glm::vec3 brightest = prism::view::maxRadiance(lights, m);  // no lit pixel exceeds this
    // [/snippet]
    return brightest.x > 1.3f && brightest.x < 1.4f ? 0 : 1;  // 0.1*0.8 + (0.8+0.5)*1
}
