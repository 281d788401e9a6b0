// The usage example of prism/scene/diffraction_object.hpp, compiled and run by tests/snippets
// (CPU only).
#include <string>

// [snippet]
#include "prism/scene/diffraction_object.hpp"
#include "prism/scene/scene_loader.hpp"
// [/snippet]

int main() {
    // [snippet]
    auto scene = prism::scene::loadScene("examples/scenes/diffraction_snake.json");
    scene.objects[0].diffraction->tableSize = 32;  // a quick build; the file asks for 128^2
    prism::scene::DiffractionObjectTables built = prism::scene::buildDiffractionTables(scene, scene.objects[0]);
    int terms = built.terms;                        // N from the material's tolerance
    const char* path = built.uniforms().variant();  // DIFFRACTION_PATH: "1" (path b)
    // [/snippet]
    return terms > 0 && std::string(path) == "1" && built.tables.integrated ? 0 : 1;
}
