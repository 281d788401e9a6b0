// Draws a Scene with only what it needs: each object's program is the variant of its
// shader that matches the scene's feature set (light counts, fog; see
// prism/feature_variants.hpp), programs are built once and shared by every draw with
// the same shader and feature set, and nothing else is built. A scene with `rain` gets
// a rain system (prism/rain/rain_system.hpp) drawn over the objects; one without gets
// none: no particle buffer, no compute update, no rain program. A scene with `water`
// is drawn on a rain-fed water scene (terrain, sky, water map; prism/water/water_scene.hpp)
// simulated for its `seconds`; one without creates no water map. An object with
// "shader": "diffraction" is drawn with the diffraction catalogue's program for the scene's
// lights and its material's path, from lookup tables built for that path only (and only
// its N terms); a scene without one builds no diffraction table or program.
//
// Usage (snippet: examples/snippets/scene_scene_renderer.cpp):
//
//     #include "prism/scene/scene_loader.hpp"
//     #include "prism/scene/scene_renderer.hpp"
//     #include "prism/shaders.hpp"
//     prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
//     prism::image::Image8 image = renderer.render(prism::scene::loadScene("examples/scenes/one_light.json"));
//     prism::image::ImageF hdr = renderer.renderF(prism::scene::loadScene("examples/scenes/one_light.json"));
//     std::size_t built = renderer.programs().size();                         // programs built so far
//     const std::vector<std::string>& drawn = renderer.lastFrame().variants;  // "phong FOG=1,..." per draw
//
// Needs a current context.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "prism/image/image.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/scene/scene.hpp"

namespace prism::rain {
class RainPrograms;
struct RainParams;
}  // namespace prism::rain
namespace prism::water {
struct HeightField;
}  // namespace prism::water
namespace prism::gl {
class Framebuffer;
}  // namespace prism::gl

namespace prism::scene {

// The rain system's parameters for a scene's rain settings (intensity class or rate,
// wind as a world vector, seed, cylinder, budget), with the cylinder's bottom reaching down
// to groundHeight when given (RainParams::groundHeight). Throws rain::RainParameterError.
rain::RainParams rainParamsFor(const RainSettings& settings, std::optional<float> groundHeight = std::nullopt);
// The same for a whole scene: with water, the ground is the lowest point of the scene's
// terrain, so the drops reach the puddles they feed. Needs scene.rain.
rain::RainParams rainParamsFor(const Scene& scene);
// The procedural terrain a scene's water settings describe (grid, cell size, seed).
water::HeightField sceneTerrain(const WaterSettings& settings);
// The terrain's lowest height: where rain and fog billboards reach down to in a scene with water.
float lowestPoint(const water::HeightField& terrain);

struct SceneFrameInfo {
    std::size_t draws = 0;
    std::vector<std::string> variants;      // "<shader> <variant name>" of each draw, in order
    std::size_t diffractionTableBytes = 0;  // GPU memory of this frame's diffraction tables
};

class SceneRenderer {
  public:
    explicit SceneRenderer(const catalog::Catalog& catalog);
    ~SceneRenderer();

    image::Image8 render(const Scene& scene);
    // The same frame drawn into an RGBA32F target, unclamped, so NaN and Inf survive to be counted.
    image::ImageF renderF(const Scene& scene);
    render::ProgramCache& programs() { return programs_; }
    const SceneFrameInfo& lastFrame() const { return lastFrame_; }
    // Rain systems created so far: one per rendered frame of a scene with rain, none
    // for scenes without (so no particle buffer, no update and no rain program).
    std::size_t rainSystemsCreated() const { return rainSystemsCreated_; }
    // Programs the rain draws used (0 until a scene with rain is rendered).
    std::size_t rainProgramsBuilt() const;
    // Water maps created so far: one per rendered frame of a scene with water.
    std::size_t waterSystemsCreated() const { return waterSystemsCreated_; }
    // Procedural terrains built so far: one per rendered frame of a scene with water, shared
    // by the water, the rain and the fog billboards of that frame.
    std::size_t terrainsBuilt() const { return terrainsBuilt_; }
    // Diffraction table sets built so far: one per distinct diffraction material (kept
    // while the renderer lives, the kDiffractionTablesKept most recent), none for scenes
    // without one; and the diffraction programs built so far.
    std::size_t diffractionTablesBuilt() const { return diffractionTablesBuilt_; }
    std::size_t diffractionProgramsBuilt() const { return diffractionPrograms_ ? diffractionPrograms_->size() : 0; }

    // Simulated time before a rain frame is drawn, so drops fill the cylinder as in a
    // running scene; fixed steps, so the image is the same on every render.
    static constexpr int kRainWarmupSteps = 30;
    static constexpr float kRainStep = 1.0f / 60.0f;
    // Distinct diffraction materials whose tables stay uploaded between frames.
    static constexpr std::size_t kDiffractionTablesKept = 8;

  private:
    void drawFrame(const Scene& scene, gl::Framebuffer& target);
    water::HeightField buildTerrain(const WaterSettings& settings);  // sceneTerrain(), counted
    void drawObjects(const Scene& scene);
    void drawRain(const Scene& scene, std::optional<float> terrainLowest);
    void drawWater(const Scene& scene, water::HeightField terrain);
    void drawFogBillboards(const Scene& scene, std::optional<float> terrainLowest);
    void drawDiffraction(const Scene& scene, const SceneObject& object, const render::FeatureSet& features,
                         float aspect);

    render::ProgramCache programs_;
    SceneFrameInfo lastFrame_;
    std::unique_ptr<rain::RainPrograms> rainPrograms_;
    std::size_t rainSystemsCreated_ = 0;
    std::size_t waterSystemsCreated_ = 0;
    std::size_t terrainsBuilt_ = 0;
    std::unique_ptr<render::ProgramCache> diffractionPrograms_;  // created with the first diffraction object
    std::size_t diffractionTablesBuilt_ = 0;
    struct DiffractionTableSet;                                            // a material, its N and its uploaded tables
    std::vector<std::unique_ptr<DiffractionTableSet>> diffractionTables_;  // most recent last
};

}  // namespace prism::scene
