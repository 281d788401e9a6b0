// The usage example of prism/scene/scene.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/shaders.hpp"
// [snippet]
#include "prism/scene/scene.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::scene::Scene scene;  // built in code instead of read from JSON
    scene.width = scene.height = 128;
    scene.lights.directional.push_back({.direction = {-0.5f, -0.6f, -0.65f}, .color = {1, 1, 1}});
    scene.fog = prism::view::Fog{.color = {0.6f, 0.65f, 0.7f}, .density = 0.1f};
    prism::scene::SceneObject ball;
    ball.mesh = "icosphere";
    ball.shader = "phong";
    ball.variantOverrides = {{"BLINN", "1"}};
    scene.objects.push_back(ball);
    // [/snippet]
    auto context = prism::gl::createContext();
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    const prism::image::Image8 image = renderer.render(scene);
    return image.width == 128 && renderer.lastFrame().draws == 1 ? 0 : 1;
}
