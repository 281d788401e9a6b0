// What a diffraction object of a scene ("shader": "diffraction") needs before any API draws
// it: the lookup tables of its material's one path (and its N), built on the CPU, with
// errors naming the object's JSON pointer. SceneRenderer (GL) and vulkanFrameOf (Vulkan)
// both build their tables here, so the two APIs draw the same material from the same tables.
//
// Usage (snippet: examples/snippets/scene_diffraction_object.cpp):
//
//     #include "prism/scene/diffraction_object.hpp"
//     #include "prism/scene/scene_loader.hpp"
//     auto scene = prism::scene::loadScene("examples/scenes/diffraction_snake.json");
//     scene.objects[0].diffraction->tableSize = 32;  // a quick build; the file asks for 128^2
//     prism::scene::DiffractionObjectTables built = prism::scene::buildDiffractionTables(scene, scene.objects[0]);
//     int terms = built.terms;                        // N from the material's tolerance
//     const char* path = built.uniforms().variant();  // DIFFRACTION_PATH: "1" (path b)
#pragma once

#include "prism/diffraction/material.hpp"
#include "prism/scene/scene.hpp"

namespace prism::scene {

struct DiffractionObjectTables {
    diffraction::MaterialTables tables;
    int terms = 0;  // N
    // The path's DIFFRACTION_PATH value and u_diffraction* scalars.
    diffraction::TableUniforms uniforms() const;
};

// The object's material (SceneObject::diffraction) -> height field -> StamBrdf -> the tables of
// its path. Throws SceneError "<file>: <pointer>/<key>: ..." for a material without parameters,
// one needing N > 200, or an unreadable height field.
DiffractionObjectTables buildDiffractionTables(const Scene& scene, const SceneObject& object);

}  // namespace prism::scene
