// Draws a water scene in three passes, sky, terrain and water surface, from GL resources
// made once: terrain and sky at construction, the water surface's only with water, the
// ripple array when rain first falls (see prism/water/water_scene.hpp, WaterSceneRenderer).
#include "prism/water/water_scene.hpp"

#include <algorithm>
#include <cstdint>

#include "prism/gl/draw_state.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/terrain_mesh.hpp"
#include "prism/water_shaders.hpp"
#include "scene_extent.hpp"

namespace prism::water {
namespace {

namespace ws = prism::water_shaders;

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
        setGridSampling(GL_NEAREST);  // read by texelFetch only (the depth is interpolated per vertex)
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
        render::setFrameUniforms(p, camera, aspect, d.lights, scene.world(), view::Material{},
                                 d.fog ? &*d.fog : nullptr);
        p.set(ws::contract::u_skyFogDistance, 2.0f * sceneExtent(scene.terrain()));
        p.set(ws::contract::u_cameraPosition, camera.eye);
    }

    // The frame: the texture units the passes read (0 sky, 1 water depth, 2 terrain
    // height, 3 ripples, 4 terrain albedo), then sky, terrain and water; the caller's state is put back.
    void draw(const view::Camera& camera, int width, int height) {
        const gl::ScopedDrawState keep;  // the caller's blend, depth, bindings and units, put back on return
        const float aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
        glViewport(0, 0, width, height);
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        bindSkyAndWaterMaps();
        drawSky(camera, aspect);
        drawTerrain(camera, aspect);
        if (scene.water() && waterIndexCount > 0) drawWaterSurface(*scene.water(), camera, aspect);
        gl::throwIfGlError("drawing the water scene");
    }

    // Units 0-2, with this frame's water depths uploaded to unit 1.
    void bindSkyAndWaterMaps() {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_CUBE_MAP, skyTexture);
        if (const WaterSystem* water = scene.water()) {
            uploadDepthTexture(water->simulation(), depthTexture);
            glActiveTexture(GL_TEXTURE1);
            glBindTexture(GL_TEXTURE_2D, depthTexture);
            glActiveTexture(GL_TEXTURE2);
            glBindTexture(GL_TEXTURE_2D, heightTexture);
        }
    }

    // Behind everything: no depth test, no depth writes.
    void drawSky(const view::Camera& camera, float aspect) {
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_BLEND);
        gl::Program& sky = program("skybox", {});
        frameUniforms(sky, camera, aspect);
        sky.set(ws::skybox::u_skybox, 0);
        sky.use();
        sky.reportUnsetUniforms();
        glBindVertexArray(skyVao);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }

    // Opaque, writing depth; darkened where wet (the WET=1 variant) in a scene with water.
    void drawTerrain(const view::Camera& camera, float aspect) {
        const WaterLook& look = scene.description().look;
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        gl::Program& terrain = program("terrain", {{"WET", scene.water() ? "1" : "0"}});
        frameUniforms(terrain, camera, aspect);
        terrain.set(ws::terrain::u_waterDepth, 1);
        terrain.set(ws::terrain::u_wetDarkening, look.wetDarkening);
        terrain.set(ws::terrain::u_wetFilmDepth, look.wetFilmDepth);
        terrain.use();
        terrain.reportUnsetUniforms();
        glBindVertexArray(terrainVao);
        glDrawElements(GL_TRIANGLES, terrainIndexCount, GL_UNSIGNED_INT, nullptr);
    }

    // Blended over the terrain, depth-tested but not written; ripples (unit 3) only in rain.
    void drawWaterSurface(const WaterSystem& water, const view::Camera& camera, float aspect) {
        const bool ripples = water.hasRain();
        if (ripples && !rippleTexture) createRipples();
        if (ripples) {
            glActiveTexture(GL_TEXTURE3);
            glBindTexture(GL_TEXTURE_2D_ARRAY, rippleTexture);
        }
        glActiveTexture(GL_TEXTURE4);
        glBindTexture(GL_TEXTURE_2D, albedoTexture);
        gl::Program& surface = program("water_surface", {{"RIPPLES", ripples ? "1" : "0"}});
        frameUniforms(surface, camera, aspect);
        waterSurfaceUniforms(surface, water);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glBlendEquation(GL_FUNC_ADD);  // premultiplied "over": nothing else may be left here
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        surface.use();
        surface.reportUnsetUniforms();
        glBindVertexArray(waterVao);
        glDrawElements(GL_TRIANGLES, waterIndexCount, GL_UNSIGNED_INT, nullptr);
    }

    void waterSurfaceUniforms(gl::Program& surface, const WaterSystem& water) {
        const WaterLook& look = scene.description().look;
        surface.set(ws::water_surface::u_skybox, 0);
        surface.set(ws::water_surface::u_waterDepth, 1);
        surface.set(ws::water_surface::u_terrainHeight, 2);
        surface.set(ws::water_surface::u_ripples, 3);
        surface.set(ws::water_surface::u_terrainAlbedo, 4);
        surface.set(ws::water_surface::u_wetDarkening, look.wetDarkening);
        surface.set(ws::water_surface::u_rippleDensity, rippleDensity(water.rainMmPerHour()));
        surface.set(ws::water_surface::u_cellSize, scene.terrain().cellSize);
        surface.set(ws::water_surface::u_waterThreshold, look.threshold);
        surface.set(ws::water_surface::u_shoreFadeDepth, look.shoreFadeDepth);
        surface.set(ws::water_surface::u_fresnelF0, look.fresnelF0);
        surface.set(ws::water_surface::u_waterTint, look.tint);
        surface.set(ws::water_surface::u_waterAbsorption, look.absorption);
        surface.set(ws::water_surface::u_rippleFrame, static_cast<float>(water.rippleFrame()));
        surface.set(ws::water_surface::u_rippleScale, look.rippleScale);
        surface.set(ws::water_surface::u_rippleStrength, rippleStrength(water.rainMmPerHour()));
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