// The usage example of prism/scene/scene_renderer.hpp, compiled and run by tests/snippets.
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    prism::image::Image8 image = renderer.render(prism::scene::loadScene("examples/scenes/one_light.json"));
    prism::image::ImageF hdr = renderer.renderF(prism::scene::loadScene("examples/scenes/one_light.json"));
    std::size_t built = renderer.programs().size();                         // programs built so far
    const std::vector<std::string>& drawn = renderer.lastFrame().variants;  // "phong FOG=1,..." per draw
    // [/snippet]
    return image.width == 512 && hdr.width == 512 && drawn.size() == 3 && built == 3 ? 0 : 1;
}
