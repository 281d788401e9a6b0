// The usage example of prism/scene/stochastic.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/scene/stochastic.hpp"
// [/snippet]
#include "prism/scene/scene_loader.hpp"

int main() {
    // [snippet]
    prism::scene::Scene scene = prism::scene::loadScene("examples/scenes/soft_shadows.json");
    scene.stochastic->sampler = prism::bluenoise::SamplerKind::Sorted;
    prism::image::Image8 image = prism::scene::renderStochastic(*scene.stochastic, scene.width, scene.height);
    // [/snippet]
    return image.width == scene.width && image.height == scene.height ? 0 : 1;
}
