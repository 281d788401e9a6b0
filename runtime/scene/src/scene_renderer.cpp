// Scene drawing with minimal, shared programs (see prism/scene_renderer.hpp).
#include "prism/scene/scene_renderer.hpp"
#include "prism/scene/diffraction_object.hpp"
#include "prism/scene/stochastic.hpp"

#include "prism/diffraction/diffraction_gl.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/draw_state.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/rain/fog_system.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_programs.hpp"
#include "prism/rain/rain_system.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_scene.hpp"
#include "prism/diffraction_shaders.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <optional>

namespace prism::scene {

rain::RainParams rainParamsFor(const RainSettings& settings, std::optional<float> groundHeight) {
    rain::RainParams p;
    if (settings.rateMillimetresPerHour) {
        p.intensity = static_cast<float>(*settings.rateMillimetresPerHour / 10.0);  // mm/h -> cm/h
    } else {
        p.intensity = rain::rainClassInfo(settings.intensityClass).intensity;
    }
    const glm::vec2 horizontal(settings.wind.x, settings.wind.z);
    p.wind.strength = glm::length(horizontal);
    if (p.wind.strength > 0.0f) p.wind.directionDegrees = glm::degrees(std::atan2(horizontal.y, horizontal.x));
    p.seed = settings.seed;
    p.radius = settings.cylinderRadius;
    p.height = settings.cylinderHeight;
    p.below = std::min(p.below, p.height);
    if (settings.particleBudget) p.budget = *settings.particleBudget;
    p.lodRings = settings.lodRings;
    p.lodFalloff = settings.lodFalloff;
    p.groundHeight = groundHeight;
    rain::validate(p);
    return p;
}

water::HeightField sceneTerrain(const WaterSettings& w) {
    water::ProceduralTerrainOptions terrain;
    terrain.width = terrain.height = static_cast<int>(w.gridSize);
    terrain.cellSize = w.cellSize;
    terrain.seed = w.seed;
    terrain.relief = w.relief;
    return water::proceduralTerrain(terrain);
}

float lowestPoint(const water::HeightField& terrain) {
    return *std::min_element(terrain.heights.begin(), terrain.heights.end());
}

rain::RainParams rainParamsFor(const Scene& scene) {
    if (!scene.water) return rainParamsFor(*scene.rain);
    return rainParamsFor(*scene.rain, lowestPoint(sceneTerrain(*scene.water)));
}

struct SceneRenderer::DiffractionTableSet {
    diffraction::DiffractionMaterial material;
    int terms = 0;
    diffraction::DiffractionTextures textures;
};

SceneRenderer::SceneRenderer(const catalog::Catalog& catalog) : programs_(catalog) {}

SceneRenderer::~SceneRenderer() = default;

std::size_t SceneRenderer::rainProgramsBuilt() const {
    return rainPrograms_ ? rainPrograms_->built() : 0;
}

void SceneRenderer::drawRain(const Scene& scene, std::optional<float> terrainLowest) {
    const rain::RainParams params = rainParamsFor(*scene.rain, terrainLowest);
    if (!rainPrograms_) rainPrograms_ = std::make_unique<rain::RainPrograms>();
    rain::RainSystem system(*rainPrograms_, params, scene.camera.eye);
    ++rainSystemsCreated_;
    for (int i = 0; i < kRainWarmupSteps; ++i) system.update(kRainStep, scene.camera.eye);

    rain::RainDrawInputs in;
    in.camera = scene.camera;
    in.aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
    in.viewportHeight = scene.height;
    in.lights.ambient = scene.lights.ambient;
    if (!scene.lights.directional.empty())
        in.lights.sun = scene.lights.directional.front();
    else
        in.lights.sun.color = glm::vec3(0.0f);
    if (!scene.lights.points.empty())
        in.lights.lamp = scene.lights.points.front();
    else
        in.lights.lamp.color = glm::vec3(0.0f);
    in.fog = scene.fog ? &*scene.fog : nullptr;
    in.technique = scene.rain->technique;
    system.draw(in);
    lastFrame_.variants.push_back("rain " + std::string(rain::techniqueName(in.technique)) + " (" +
                                  std::to_string(system.particleCount()) + " particles)");
}

void SceneRenderer::drawFogBillboards(const Scene& scene, std::optional<float> terrainLowest) {
    // With water, the billboards fade into the terrain's lowest ground.
    const float groundHeight = terrainLowest.value_or(scene.fogGroundHeight);
    const rain::SceneFog fog = rain::fogOverGround(*scene.fog, *scene.fogBillboards, groundHeight);
    if (!rainPrograms_) rainPrograms_ = std::make_unique<rain::RainPrograms>();
    rain::FogSystem system(*rainPrograms_, fog, scene.camera.eye);
    system.update(kRainStep, scene.camera.eye, glm::vec3(0.0f));
    const float aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
    system.draw(scene.camera, aspect, &*scene.fog, 0.0f);
    lastFrame_.variants.push_back("fog_billboards FOG=1 (" + std::to_string(fog.billboards.count) + " billboards)");
}

void SceneRenderer::drawWater(const Scene& scene, water::HeightField terrain) {
    const WaterSettings& w = *scene.water;
    water::WaterSceneDescription d;
    d.terrain = std::move(terrain);
    water::PermeabilityOptions soil;
    soil.soilMmPerHour = w.soilMillimetresPerHour;
    soil.clayMmPerHour = std::min(soil.clayMmPerHour, w.soilMillimetresPerHour);
    d.permeability = water::proceduralPermeability(d.terrain, soil);
    d.rainMmPerHour = w.rainRateMillimetresPerHour;
    if (scene.rain) {  // the scene's rain feeds the water
        if (scene.rain->rateMillimetresPerHour) {
            d.rainMmPerHour = *scene.rain->rateMillimetresPerHour;
        } else {
            d.rainMmPerHour = water::rainRateMmPerHour(scene.rain->intensityClass);
        }
    }
    d.lights = scene.lights;
    d.fog = scene.fog;
    d.backend = w.backend;  // both steps give the same water
    d.sky.cloudCover = w.cloudCover;
    water::WaterScene waterScene(std::move(d));
    ++waterSystemsCreated_;
    waterScene.advance(w.seconds);
    water::WaterSceneRenderer renderer(waterScene);
    renderer.draw(scene.camera, scene.width, scene.height);
    lastFrame_.variants.push_back("water " + std::to_string(w.gridSize) + "x" + std::to_string(w.gridSize) + " after " +
                                  std::to_string(static_cast<int>(w.seconds)) + " s of rain");
}

void SceneRenderer::drawDiffraction(const Scene& scene, const SceneObject& object, const render::FeatureSet& features,
                                    float aspect) {
    if (!object.diffraction) (void)buildDiffractionTables(scene, object);  // throws, naming the object
    const diffraction::DiffractionMaterial& m = *object.diffraction;
    auto cached = std::find_if(diffractionTables_.begin(), diffractionTables_.end(),
                               [&](const auto& set) { return set->material == m; });
    if (cached == diffractionTables_.end()) {
        DiffractionObjectTables built = buildDiffractionTables(scene, object);
        const int builtTerms = built.terms;
        std::optional<diffraction::DiffractionTextures> uploaded;
        if (built.tables.spectral) {
            uploaded.emplace(*built.tables.spectral);
        } else if (built.tables.integrated) {
            uploaded.emplace(*built.tables.integrated);
        } else {
            uploaded.emplace(*built.tables.volume);
        }
        ++diffractionTablesBuilt_;
        if (diffractionTables_.size() == kDiffractionTablesKept) diffractionTables_.erase(diffractionTables_.begin());
        diffractionTables_.push_back(
            std::make_unique<DiffractionTableSet>(DiffractionTableSet{m, builtTerms, std::move(*uploaded)}));
        cached = std::prev(diffractionTables_.end());
    }
    const diffraction::DiffractionTextures* textures = &(*cached)->textures;
    const int terms = (*cached)->terms;
    lastFrame_.diffractionTableBytes += textures->bytes();

    if (!diffractionPrograms_)
        diffractionPrograms_ = std::make_unique<render::ProgramCache>(diffraction::diffractionPrograms().catalog());
    const auto* shader = catalog::findShader(diffractionPrograms_->catalog(), "diffraction");
    render::VariantValues requested = object.variantOverrides;
    requested.emplace_back("DIFFRACTION_PATH", textures->variant());  // the material decides the path
    const render::VariantValues variant = variantFor(*shader, features, requested);
    gl::Program& program = diffractionPrograms_->get("diffraction", variant);
    render::GpuMesh mesh(render::meshForShader("diffraction", render::namedMesh(object.mesh, object.subdivision)),
                         diffractionPrograms_->catalog().contractAttributes);
    render::setFrameUniforms(program, scene.camera, aspect, scene.lights, object.world, object.material,
                             scene.fog ? &*scene.fog : nullptr);
    program.set(diffraction_shaders::diffraction::u_diffractionTangent,
                glm::vec3(static_cast<float>(m.tangent[0]), static_cast<float>(m.tangent[1]),
                          static_cast<float>(m.tangent[2])));
    program.set(diffraction_shaders::diffraction::u_diffractionRadial, m.radialTangent ? 1.0f : 0.0f);
    textures->apply(program);
    program.use();
    mesh.draw(program);
    ++lastFrame_.draws;
    lastFrame_.variants.push_back(
        "diffraction " + std::string(diffractionPrograms_->variantOf("diffraction", variant).name) + " (path " +
        m.path + ", N=" + std::to_string(terms) + ", " + std::to_string(m.tableSize) + "^2, " +
        std::to_string(textures->bytes() / 1024) + " KiB)");
}

// One frame: the water scene (terrain, sky, water) first, since objects stand in it, then the
// objects, then rain and fog billboards over them. The terrain is built once per frame; rain
// and billboards reach down to its lowest point.
image::Image8 SceneRenderer::render(const Scene& scene) {
    lastFrame_ = {};
    if (scene.stochastic) return renderStochastic(*scene.stochastic, scene.width, scene.height);  // CPU, no draws
    const gl::ScopedDrawState keep;  // declared before fb: restored after fb is deleted
    gl::Framebuffer fb(scene.width, scene.height, gl::ColorFormat::Rgba8);
    drawFrame(scene, fb);
    return fb.readImage8();
}

image::ImageF SceneRenderer::renderF(const Scene& scene) {
    lastFrame_ = {};
    if (scene.stochastic) return image::toImageF(renderStochastic(*scene.stochastic, scene.width, scene.height));
    const gl::ScopedDrawState keep;
    gl::Framebuffer fb(scene.width, scene.height, gl::ColorFormat::Rgba32F);
    drawFrame(scene, fb);
    return fb.readImageF();
}

void SceneRenderer::drawFrame(const Scene& scene, gl::Framebuffer& fb) {
    fb.bind();
    const glm::vec4 background = scene.fog ? glm::vec4(scene.fog->color, 1.0f) : scene.background;
    fb.clear({background.r, background.g, background.b, background.a});
    std::optional<float> terrainLowest;
    if (scene.water) {
        water::HeightField terrain = buildTerrain(*scene.water);
        terrainLowest = lowestPoint(terrain);
        drawWater(scene, std::move(terrain));
        fb.bind();
    }
    drawObjects(scene);
    if (scene.rain) drawRain(scene, terrainLowest);
    if (scene.fog && scene.fogBillboards && *scene.fogBillboards > 0.0f) drawFogBillboards(scene, terrainLowest);
    glFinish();
    gl::throwIfGlError("rendering " + scene.file);
}

water::HeightField SceneRenderer::buildTerrain(const WaterSettings& settings) {
    ++terrainsBuilt_;
    return sceneTerrain(settings);
}

// Each object with its shader's variant for the scene's lights and fog, depth-tested, opaque.
void SceneRenderer::drawObjects(const Scene& scene) {
    const render::FeatureSet features = render::featuresOf(scene.lights, scene.fog.has_value());
    const float aspect = static_cast<float>(scene.width) / static_cast<float>(scene.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    for (const auto& object : scene.objects) {
        if (object.shader == "diffraction") {
            drawDiffraction(scene, object, features, aspect);
            continue;
        }
        const auto* shader = catalog::findShader(programs_.catalog(), object.shader);
        if (!shader) programs_.variantOf(object.shader, {});  // throws render::UnknownShaderError with the list
        const render::VariantValues variant = variantFor(*shader, features, object.variantOverrides);
        gl::Program& program = programs_.get(object.shader, variant);
        render::GpuMesh mesh(render::meshForShader(object.shader, render::namedMesh(object.mesh, object.subdivision)),
                             programs_.catalog().contractAttributes);
        program.use();
        render::setFrameUniforms(program, scene.camera, aspect, scene.lights, object.world, object.material,
                                 scene.fog ? &*scene.fog : nullptr);
        mesh.draw(program);
        ++lastFrame_.draws;
        lastFrame_.variants.push_back(object.shader + " " +
                                      std::string(programs_.variantOf(object.shader, variant).name));
    }
}

}  // namespace prism::scene
