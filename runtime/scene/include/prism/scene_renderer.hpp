// Draws a Scene with only what it needs: each object's program is the variant of its
// shader that matches the scene's feature set (light counts, fog; see
// prism/feature_variants.hpp), programs are built once and shared by every draw with
// the same shader and feature set, and nothing else is built.
//
//     prism::SceneRenderer renderer(prism::shaders::kCatalog);
//     prism::Image8 image = renderer.render(prism::loadScene("examples/scenes/one_light.json"));
//     renderer.programs().size();          // programs built so far
//     renderer.lastFrame().variants;       // "phong DIRECTIONAL_LIGHTS=1,..." per draw
//
// Needs a current context.
#pragma once

#include <string>
#include <vector>

#include "prism/image.hpp"
#include "prism/program_cache.hpp"
#include "prism/scene.hpp"

namespace prism {

struct SceneFrameInfo {
    std::size_t draws = 0;
    std::vector<std::string> variants;  // "<shader> <variant name>" of each draw, in order
};

class SceneRenderer {
public:
    explicit SceneRenderer(const catalog::Catalog& catalog) : programs_(catalog) {}

    Image8 render(const Scene& scene);
    ProgramCache& programs() { return programs_; }
    const SceneFrameInfo& lastFrame() const { return lastFrame_; }

private:
    ProgramCache programs_;
    SceneFrameInfo lastFrame_;
};

}  // namespace prism
