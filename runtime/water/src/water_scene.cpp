// The water scene and its renderer (see water_scene.hpp).
#include "prism/water/water_scene.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/terrain_mesh.hpp"
#include "prism/water_shaders.hpp"

namespace prism::water {

// --- scene::Scene -----------------------------------------------------------------------------

view::Lights WaterSceneDescription::defaultSun() {
    view::Lights l;
    l.ambient = {0.32f, 0.35f, 0.40f};
    l.directional.push_back({.direction = {-0.45f, -0.55f, 0.70f}, .color = {0.85f, 0.82f, 0.74f}});
    return l;
}

WaterSystem::WaterSystem(const HeightField& terrain, std::vector<float> permeability, const WaterParams& params,
                         SimulationBackend backend, double rainMmPerHour) {
    if (backend == SimulationBackend::Fastest) backend = chooseFastestBackend(terrain, permeability, params).backend;
    if (backend == SimulationBackend::Gpu)
        simulation_ = std::make_unique<GpuWaterSimulation>(terrain, std::move(permeability), params);
    else
        simulation_ = std::make_unique<CpuWaterSimulation>(terrain, std::move(permeability), params);
    setRain(rainMmPerHour);
}

void WaterSystem::setRain(double mmPerHour) {
    if (!(mmPerHour >= 0.0) || !std::isfinite(mmPerHour))
        throw std::invalid_argument("WaterSystem: the rain rate must be a finite number of mm/h >= 0");
    rainMmPerHour_ = mmPerHour;
    simulation_->setRainRate(mmPerHourToMetresPerSecond(mmPerHour));
}

SubstepPlan WaterSystem::advance(double dt) {
    const SubstepPlan plan = simulation_->advance(dt);
    rippleFrame_ = std::fmod(rippleFrame_ + dt * rippleFramesPerSecond(rainMmPerHour_), RippleFrames::kFrames);
    return plan;
}

WaterScene::WaterScene(WaterSceneDescription d) : description_(std::move(d)) {
    if (description_.terrain.cellCount() == 0 && description_.terrain.heights.empty())
        description_.terrain = proceduralTerrain();
    validate(description_.terrain, "WaterScene terrain");
    if (description_.permeability.empty()) description_.permeability = proceduralPermeability(description_.terrain);
    if (description_.water)
        water_ = std::make_unique<WaterSystem>(description_.terrain, description_.permeability, description_.params,
                                               description_.backend, description_.rainMmPerHour);
}

void WaterScene::advance(double dt) {
    if (water_) water_->advance(dt);
}

glm::mat4 WaterScene::world() const {
    const HeightField& t = description_.terrain;
    return glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f * t.sizeX(), static_cast<float>(t.origin), -0.5f * t.sizeZ()));
}

namespace {

// Copies the compensated depths of either simulation into the RG32F depth texture:
// on the GPU for the compute path, from the CPU arrays otherwise.
void uploadDepthTexture(const WaterSimulation& simulation, GLuint texture) {
    if (const auto* gpu = dynamic_cast<const GpuWaterSimulation*>(&simulation)) {
        gpu->uploadDepthTexture(texture);
        return;
    }
    const std::vector<glm::vec2> pairs = simulation.depthPairs();
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, simulation.width(), simulation.height(), GL_RG, GL_FLOAT, pairs.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

float meanHeight(const HeightField& t) {
    double s = 0.0;
    for (float h : t.heights) s += h;
    return static_cast<float>(s / static_cast<double>(t.heights.size()));
}

float extent(const HeightField& t) {
    return std::max({t.sizeX(), t.sizeZ(), t.cellSize});
}

}  // namespace

view::Camera overviewCamera(const HeightField& t) {
    const float e = extent(t), mid = meanHeight(t);
    view::Camera c;
    c.eye = {0.66f * e, mid + 0.40f * e, 0.84f * e};
    c.target = {0.0f, mid - 0.08f * e, 0.0f};
    c.fovYDegrees = 45.0f;
    c.nearPlane = 0.01f * e;
    c.farPlane = 20.0f * e;
    return c;
}

view::Camera groundCamera(const HeightField& t) {
    const float e = extent(t), mid = meanHeight(t);
    view::Camera c;
    c.eye = {-0.42f * e, mid + 0.16f * e, 0.40f * e};
    c.target = {0.08f * e, mid - 0.04f * e, -0.05f * e};
    c.fovYDegrees = 50.0f;
    c.nearPlane = 0.005f * e;
    c.farPlane = 20.0f * e;
    return c;
}

// --- Renderer ----------------------------------------------------------------------------

namespace {

namespace ws = prism::water_shaders;

constexpr GLenum kTextureCubeMapSeamless = 0x884F;  // GL_TEXTURE_CUBE_MAP_SEAMLESS (3.2 core)

template <class T>
void setIfPresent(gl::Program& p, std::string_view name, const T& value) {
    if (p.hasUniform(name)) p.set(name, value);
}

}  // namespace

struct WaterSceneRenderer::Impl {
    const WaterScene& scene;
    render::ProgramCache cache{ws::kCatalog};
    SceneRenderStats counts;
    GLuint terrainVao = 0, terrainBuffers[5] = {0, 0, 0, 0, 0};  // positions, normals, uvs, colours, indices
    GLsizei terrainIndexCount = 0;
    GLuint skyVao = 0, skyVbo = 0, skyTexture = 0;
    GLuint waterVao = 0, waterIndices = 0, depthTexture = 0, heightTexture = 0;
    GLsizei waterIndexCount = 0;
    GLuint rippleTexture = 0;
    GLuint albedoTexture = 0;  // the terrain's albedo per cell, for the ground seen through water
    // The names above are owned here, through prism::gl handles (deleted with the renderer).
    std::vector<gl::Buffer> ownedBuffers;
    std::vector<gl::Texture> ownedTextures;
    std::vector<gl::VertexArray> ownedVertexArrays;

    explicit Impl(const WaterScene& s) : scene(s) {}

    GLuint newBuffer(GLenum target, GLsizeiptr bytes, const void* data) {
        const GLuint b = ownedBuffers.emplace_back(gl::Buffer::create()).id();
        glBindBuffer(target, b);
        glBufferData(target, bytes, data, GL_STATIC_DRAW);
        ++counts.buffers;
        return b;
    }
    GLuint newTexture() {
        const GLuint t = ownedTextures.emplace_back(gl::Texture::create()).id();
        ++counts.textures;
        return t;
    }
    GLuint newVertexArray() {
        const GLuint a = ownedVertexArrays.emplace_back(gl::VertexArray::create()).id();
        ++counts.vertexArrays;
        return a;
    }

    void createTerrain() {
        const TerrainMesh t = makeTerrainMesh(scene.terrain(), scene.permeability());
        terrainVao = newVertexArray();
        glBindVertexArray(terrainVao);
        const auto attribute = [&](int slot, std::string_view name, int components, const void* data,
                                   std::size_t bytes) {
            terrainBuffers[slot] = newBuffer(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data);
            const GLuint loc = static_cast<GLuint>(catalog::attributeLocation(ws::kCatalog, name));
            glEnableVertexAttribArray(loc);
            glVertexAttribPointer(loc, components, GL_FLOAT, GL_FALSE, 0, nullptr);
        };
        attribute(0, "a_position", 3, t.mesh.positions.data(), t.mesh.positions.size() * sizeof(glm::vec3));
        attribute(1, "a_normal", 3, t.mesh.normals.data(), t.mesh.normals.size() * sizeof(glm::vec3));
        attribute(2, "a_uv", 2, t.mesh.uvs.data(), t.mesh.uvs.size() * sizeof(glm::vec2));
        attribute(3, "a_color", 4, t.colors.data(), t.colors.size() * sizeof(glm::vec4));
        terrainBuffers[4] =
            newBuffer(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(t.mesh.indices.size() * sizeof(std::uint32_t)),
                      t.mesh.indices.data());
        terrainIndexCount = static_cast<GLsizei>(t.mesh.indices.size());
        glBindVertexArray(0);
        if (scene.hasWater()) {
            std::vector<std::uint8_t> rgba(t.colors.size() * 4);
            for (std::size_t i = 0; i < t.colors.size(); ++i)
                for (int c = 0; c < 4; ++c)
                    rgba[i * 4 + static_cast<std::size_t>(c)] =
                        static_cast<std::uint8_t>(std::clamp(t.colors[i][c], 0.0f, 1.0f) * 255.0f + 0.5f);
            albedoTexture = newTexture();
            glBindTexture(GL_TEXTURE_2D, albedoTexture);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, scene.terrain().width, scene.terrain().height, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, rgba.data());
            setGridSampling(GL_LINEAR);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }

    void createSky() {
        const CubeFaces faces = proceduralSky(scene.description().sky);
        skyTexture = newTexture();
        glBindTexture(GL_TEXTURE_CUBE_MAP, skyTexture);
        for (int f = 0; f < 6; ++f)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(f), 0, GL_RGBA8, faces.size, faces.size,
                         0, GL_RGBA, GL_UNSIGNED_BYTE, faces.rgba[static_cast<std::size_t>(f)].data());
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        // A unit cube as 12 triangles (36 corners); only positions.
        const float p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
        const int faceCorners[6][4] = {{1, 5, 6, 2}, {4, 0, 3, 7}, {3, 2, 6, 7},
                                       {4, 5, 1, 0}, {5, 4, 7, 6}, {0, 1, 2, 3}};
        std::vector<float> v;
        for (const auto& q : faceCorners)
            for (int k : {0, 1, 2, 0, 2, 3})
                for (int c = 0; c < 3; ++c) v.push_back(p[q[k]][c]);
        skyVao = newVertexArray();
        glBindVertexArray(skyVao);
        skyVbo = newBuffer(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data());
        const GLuint loc = static_cast<GLuint>(catalog::attributeLocation(ws::kCatalog, "a_position"));
        glEnableVertexAttribArray(loc);
        glVertexAttribPointer(loc, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glBindVertexArray(0);
    }

    void createWaterSurface() {
        const HeightField& t = scene.terrain();
        heightTexture = newTexture();
        glBindTexture(GL_TEXTURE_2D, heightTexture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, t.width, t.height, 0, GL_RED, GL_FLOAT, t.heights.data());
        setGridSampling(GL_LINEAR);  // the fragment stage interpolates; the vertex stage uses texelFetch
        depthTexture = newTexture();
        glBindTexture(GL_TEXTURE_2D, depthTexture);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, t.width, t.height, 0, GL_RG, GL_FLOAT, nullptr);
        setGridSampling(GL_LINEAR);  // the terrain's WET lookup interpolates; texelFetch ignores it
        glBindTexture(GL_TEXTURE_2D, 0);
        const std::vector<std::uint32_t> idx = gridIndices(t.width, t.height);
        waterVao = newVertexArray();  // no attributes: vertices come from gl_VertexID
        glBindVertexArray(waterVao);
        waterIndices = newBuffer(GL_ELEMENT_ARRAY_BUFFER,
                                 static_cast<GLsizeiptr>(std::max<std::size_t>(1, idx.size()) * sizeof(std::uint32_t)),
                                 idx.empty() ? nullptr : idx.data());
        waterIndexCount = static_cast<GLsizei>(idx.size());
        glBindVertexArray(0);
        counts.waterSurface = true;
    }

    static void setGridSampling(GLint filter) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }

    void createRipples() {
        const RippleFrames r = proceduralRipples({});
        rippleTexture = newTexture();
        glBindTexture(GL_TEXTURE_2D_ARRAY, rippleTexture);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, r.size, r.size, RippleFrames::kFrames, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, r.rgba.data());
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        counts.rippleTextures = true;
    }

    gl::Program& program(const char* name, const render::VariantValues& requested) {
        const auto& d = scene.description();
        const catalog::Shader* shader = catalog::findShader(ws::kCatalog, name);
        return cache.get(name, render::variantFor(*shader, render::featuresOf(d.lights, d.fog.has_value()), requested));
    }

    void frameUniforms(gl::Program& p, const view::Camera& camera, float aspect) {
        const auto& d = scene.description();
        render::setFrameUniforms(p, camera, aspect, d.lights, scene.world(), view::Material{}, d.fog ? &*d.fog : nullptr);
        setIfPresent(p, "u_skyFogDistance", 2.0f * extent(scene.terrain()));
        setIfPresent(p, "u_cameraPosition", camera.eye);
    }

    void draw(const view::Camera& camera, int width, int height) {
        const auto& d = scene.description();
        const WaterSystem* water = scene.water();
        const float aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
        glViewport(0, 0, width, height);
        glEnable(kTextureCubeMapSeamless);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_CUBE_MAP, skyTexture);
        if (water) {
            uploadDepthTexture(water->simulation(), depthTexture);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, depthTexture);
            glActiveTexture(GL_TEXTURE2);
            glBindTexture(GL_TEXTURE_2D, heightTexture);
        }
        // Sky: behind everything, no depth.
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_BLEND);
        gl::Program& sky = program("skybox", {});
        frameUniforms(sky, camera, aspect);
        setIfPresent(sky, "u_skybox", 0);
        sky.use();
        glBindVertexArray(skyVao);
        glDrawArrays(GL_TRIANGLES, 0, 36);
        // Terrain.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        gl::Program& terrain = program("terrain", {{"WET", water ? "1" : "0"}});
        frameUniforms(terrain, camera, aspect);
        setIfPresent(terrain, "u_waterDepth", 1);
        setIfPresent(terrain, "u_wetDarkening", d.look.wetDarkening);
        setIfPresent(terrain, "u_wetFilmDepth", d.look.wetFilmDepth);
        terrain.use();
        glBindVertexArray(terrainVao);
        glDrawElements(GL_TRIANGLES, terrainIndexCount, GL_UNSIGNED_INT, nullptr);
        // Water: blended over the terrain, depth-tested but not written.
        if (water && waterIndexCount > 0) {
            const bool ripples = water->hasRain();
            if (ripples && !rippleTexture) createRipples();
            if (ripples) {
                glActiveTexture(GL_TEXTURE3);
                glBindTexture(GL_TEXTURE_2D_ARRAY, rippleTexture);
            }
            glActiveTexture(GL_TEXTURE4);
            glBindTexture(GL_TEXTURE_2D, albedoTexture);
            gl::Program& surface = program("water_surface", {{"RIPPLES", ripples ? "1" : "0"}});
            frameUniforms(surface, camera, aspect);
            setIfPresent(surface, "u_skybox", 0);
            setIfPresent(surface, "u_waterDepth", 1);
            setIfPresent(surface, "u_terrainHeight", 2);
            setIfPresent(surface, "u_ripples", 3);
            setIfPresent(surface, "u_terrainAlbedo", 4);
            setIfPresent(surface, "u_wetDarkening", d.look.wetDarkening);
            setIfPresent(surface, "u_rippleDensity", rippleDensity(water->rainMmPerHour()));
            setIfPresent(surface, "u_cellSize", scene.terrain().cellSize);
            setIfPresent(surface, "u_waterThreshold", d.look.threshold);
            setIfPresent(surface, "u_shoreFadeDepth", d.look.shoreFadeDepth);
            setIfPresent(surface, "u_fresnelF0", d.look.fresnelF0);
            setIfPresent(surface, "u_waterTint", d.look.tint);
            setIfPresent(surface, "u_waterAbsorption", d.look.absorption);
            setIfPresent(surface, "u_rippleFrame", static_cast<float>(water->rippleFrame()));
            setIfPresent(surface, "u_rippleScale", d.look.rippleScale);
            setIfPresent(surface, "u_rippleStrength", rippleStrength(water->rainMmPerHour()));
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
            glDepthFunc(GL_LEQUAL);
            surface.use();
            glBindVertexArray(waterVao);
            glDrawElements(GL_TRIANGLES, waterIndexCount, GL_UNSIGNED_INT, nullptr);
            glDepthMask(GL_TRUE);
            glDepthFunc(GL_LESS);
            glDisable(GL_BLEND);
        }
        glBindVertexArray(0);
        glUseProgram(0);
        glActiveTexture(GL_TEXTURE3);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        for (GLenum unit : {GL_TEXTURE4, GL_TEXTURE2, GL_TEXTURE1}) {
            glActiveTexture(unit);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        gl::throwIfGlError("drawing the water scene");
    }
};

WaterSceneRenderer::WaterSceneRenderer(const WaterScene& scene) : impl_(std::make_unique<Impl>(scene)) {
    impl_->createSky();
    impl_->createTerrain();
    if (scene.hasWater()) impl_->createWaterSurface();
    gl::throwIfGlError("creating the water scene's GL resources");
}

WaterSceneRenderer::~WaterSceneRenderer() = default;

void WaterSceneRenderer::draw(const view::Camera& camera, int width, int height) {
    impl_->draw(camera, width, height);
}

image::Image8 WaterSceneRenderer::renderImage(const view::Camera& camera, int width, int height) {
    gl::Framebuffer fb(width, height);
    fb.bind();
    impl_->draw(camera, width, height);
    image::Image8 image = fb.readImage8();
    gl::Framebuffer::bindDefault();
    return image;
}

SceneRenderStats WaterSceneRenderer::stats() const {
    SceneRenderStats s = impl_->counts;
    s.programs = impl_->cache.size();
    return s;
}

render::ProgramCache& WaterSceneRenderer::programCache() {
    return impl_->cache;
}

}  // namespace prism::water
