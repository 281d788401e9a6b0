// The usage example of prism/scene/scene_loader.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/scene/scene_loader.hpp"
// [/snippet]

int main() {
    const std::string text = R"({"objects": [{"mesh": "cube", "material": {"shader": "flat"}}]})";
    // [snippet]
    prism::scene::Scene scene = prism::scene::loadScene("examples/scenes/one_light.json");
    prism::scene::Scene same = prism::scene::parseScene(text, "inline.json");
    // [/snippet]
    try {
        prism::scene::parseScene(R"({"fogg": {}})", "typo.json");
        return 1;  // an unknown key must be an error
    } catch (const prism::scene::SceneError&) {
    }
    return scene.objects.size() == 3 && same.objects.size() == 1 ? 0 : 1;
}
