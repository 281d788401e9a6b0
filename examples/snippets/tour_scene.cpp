// docs/runtime.md, "Scenes": a JSON scene (docs/scenes.md) rendered with only the variants it
// needs. Compiled and run by tests/snippets (snippets.tour_scene).
// [snippet]
#include <iostream>

#include "prism/gl/gl_context.hpp"
#include "prism/image/png_io.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/shaders.hpp"

int main() {
    // Parsing needs no context; errors name the file and JSON path (/lights/2/direction: ...).
    prism::scene::Scene scene = prism::scene::loadScene("examples/scenes/one_light.json");

    auto context = prism::gl::createContext();
    prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
    prism::image::Image8 image = renderer.render(scene);
    prism::image::writePng("out/one_light.png", image);

    for (const std::string& v : renderer.lastFrame().variants) std::cout << v << "\n";
    std::cout << renderer.programs().size() << " program(s) for " << renderer.lastFrame().draws << " draw(s)\n";
    return renderer.programs().size() <= renderer.lastFrame().draws ? 0 : 1;
}
// [/snippet]
