// The rain scene (see prism/rain/rain_scene.hpp).
#include "prism/rain/rain_scene.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

#include "prism/gl/gl.hpp"
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/rain_shaders.hpp"

namespace prism::rain {
namespace {

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

constexpr float kBulbRadius = 0.18f;
constexpr float kPostWidth = 0.12f;

}  // namespace

geometry::Mesh makeRainGround(const GroundDesc& g) {
    if (!(g.size > 0.0f) || g.cells < 1 || g.cells > 2048 || !std::isfinite(g.hillHeight) || !(g.flatRadius >= 0.0f))
        throw RainParameterError(
            "rain: ground needs size > 0, cells in 1..2048, a finite hill height and flatRadius >= 0");
    geometry::Mesh mesh =
        geometry::makeGrid(g.size, g.size, static_cast<std::uint32_t>(g.cells), static_cast<std::uint32_t>(g.cells));
    if (g.hillHeight != 0.0f) {
        for (auto& p : mesh.positions) {
            const float r = std::sqrt(p.x * p.x + p.z * p.z);
            const float swell = smoothstep(g.flatRadius, g.flatRadius * 2.5f, r);
            const float wave = 0.55f + 0.45f * std::sin(p.x * 0.045f + 0.7f) * std::cos(p.z * 0.037f - 0.4f);
            p.y = g.hillHeight * swell * wave;
        }
        mesh.normals.clear();
        geometry::computeVertexNormals(mesh);
    }
    return mesh;
}

RainSceneDesc defaultRainScene() {
    RainSceneDesc d;
    d.camera = rainSceneView(0);
    RainParams rain;
    rain.seed = 2013;
    rain.wind.directionDegrees = 200.0f;
    rain.wind.strength = 0.0f;
    d.rain = rain;
    return d;
}

view::Camera rainSceneView(int view) {
    view::Camera c;
    c.fovYDegrees = 60.0f;
    c.nearPlane = 0.1f;
    c.farPlane = 250.0f;
    switch (view) {
        case 1:  // from beyond the lamp, looking back up the road and into the sun's side
            c.eye = {-1.5f, 1.7f, -14.0f};
            c.target = {1.0f, 2.4f, 0.0f};
            break;
        case 2:  // close to the lamp, looking up past it into the rain
            c.eye = {0.2f, 1.6f, -2.2f};
            c.target = {2.0f, 4.4f, -6.0f};
            break;
        default:  // along the road, past the lamp
            c.eye = {0.0f, 1.7f, 6.0f};
            c.target = {1.2f, 2.0f, -6.0f};
            break;
    }
    return c;
}

RainScene::RainScene(const RainSceneDesc& desc) : desc_(desc), programs_(std::make_unique<RainPrograms>()) {
    if (desc_.rain) validate(*desc_.rain);
    if (desc_.fog) validate(*desc_.fog);
    validateEye(desc_.camera.eye);
    const auto& contract = programs_->catalog().contractAttributes;
    ground_ = std::make_unique<render::GpuMesh>(makeRainGround(desc_.ground), contract);
    if (desc_.showLampBulb) {
        bulb_ = std::make_unique<render::GpuMesh>(geometry::makeIcosphere(1.0f, 2), contract);
        post_ = std::make_unique<render::GpuMesh>(geometry::makeCube(1.0f), contract);
    }
    // Only what the scene has: the rain system (buffers, compute, streak texture) and
    // the fog billboards exist only when asked for.
    if (desc_.rain) rain_ = std::make_unique<RainSystem>(*programs_, *desc_.rain, desc_.camera.eye);
    if (desc_.fog && desc_.fog->billboards.strength > 0.0f)
        fog_ = std::make_unique<FogSystem>(*programs_, *desc_.fog, desc_.camera.eye);
}

RainScene::~RainScene() = default;

void RainScene::setCamera(const view::Camera& camera) {
    validateEye(camera.eye);
    desc_.camera = camera;
}

void RainScene::update(float dt) {
    const float step = clampStep(dt);
    time_ += step;
    if (rain_) rain_->update(step, desc_.camera.eye);
    if (fog_) fog_->update(step, desc_.camera.eye, rain_ ? rain_->wind() : glm::vec3(0.0f));
}

std::vector<std::string> RainScene::programsInUse() const {
    return programs_->used();
}

void RainScene::draw(int width, int height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("rain: scene size must be positive");
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const view::Fog* fog = desc_.fog ? &desc_.fog->distance : nullptr;
    glViewport(0, 0, width, height);
    // The sky is the farthest thing there is: with fog it takes the fog's colour as
    // applyFog() would at the far plane.
    glm::vec3 sky = desc_.skyColor;
    if (fog) sky = glm::mix(fog->color, sky, std::exp(-std::min(fog->density * desc_.camera.farPlane, 80.0f)));
    glClearColor(sky.r, sky.g, sky.b, 1.0f);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    gl::Program& ground = programs_->get("ground", {{"FOG", fog ? "1" : "0"}});
    ground.use();
    const RainLights& l = desc_.lights;
    ground.set(rain_shaders::ground::u_view, desc_.camera.view());
    ground.set(rain_shaders::ground::u_projection, desc_.camera.projection(aspect));
    ground.set(rain_shaders::ground::u_cameraPosition, desc_.camera.eye);
    ground.set(rain_shaders::ground::u_ambient, l.ambient);
    ground.set(rain_shaders::ground::u_sunDirection, glm::normalize(l.sun.direction));
    ground.set(rain_shaders::ground::u_sunColor, l.sun.color);
    ground.set(rain_shaders::ground::u_lampPosition, l.lamp.position);
    ground.set(rain_shaders::ground::u_lampColor, l.lamp.color);
    ground.set(rain_shaders::ground::u_lampRange, l.lampRange);
    ground.set(rain_shaders::ground::u_shininess, desc_.ground.shininess);
    ground.set(rain_shaders::ground::u_specular, desc_.ground.specular);
    if (fog) {
        ground.set(rain_shaders::ground::u_fogColor, fog->color);
        ground.set(rain_shaders::ground::u_fogDensity, fog->density);
    }
    ground.set(rain_shaders::ground::u_world, glm::mat4(1.0f));
    ground.set(rain_shaders::ground::u_color, glm::vec4(desc_.ground.color, 1.0f));
    ground.set(rain_shaders::ground::u_emissive, 0.0f);
    ground.reportUnsetUniforms();
    ground_->draw();
    if (post_) {
        // The lamp: a dark post from the ground up to a glowing bulb.
        const glm::vec3 lamp = l.lamp.position;
        const float postHeight = std::max(lamp.y - kBulbRadius, 0.01f);
        glm::mat4 post = glm::translate(glm::mat4(1.0f), glm::vec3(lamp.x, 0.5f * postHeight, lamp.z));
        post = glm::scale(post, glm::vec3(kPostWidth, postHeight, kPostWidth));
        ground.set(rain_shaders::ground::u_world, post);
        ground.set(rain_shaders::ground::u_color, glm::vec4(0.08f, 0.08f, 0.09f, 1.0f));
        post_->draw();
    }
    if (bulb_) {
        const glm::vec3 lamp = l.lamp.position;
        const float m = std::max({l.lamp.color.r, l.lamp.color.g, l.lamp.color.b, 1e-6f});
        ground.set(rain_shaders::ground::u_world,
                   glm::scale(glm::translate(glm::mat4(1.0f), lamp), glm::vec3(kBulbRadius)));
        ground.set(rain_shaders::ground::u_color, glm::vec4(l.lamp.color / m, 1.0f));
        ground.set(rain_shaders::ground::u_emissive, 1.0f);
        bulb_->draw();
    }
    if (fog_) fog_->draw(desc_.camera, aspect, fog, time_);
    if (rain_) {
        RainDrawInputs in;
        in.camera = desc_.camera;
        in.aspect = aspect;
        in.viewportHeight = height;
        in.lights = desc_.lights;
        in.fog = fog;
        in.technique = desc_.technique;
        rain_->draw(in);
    }
    gl::throwIfGlError("rain: drawing the scene");
}

image::Image8 RainScene::render(int width, int height) {
    gl::Framebuffer fb(width, height, gl::ColorFormat::Rgba8);
    fb.bind();
    draw(width, height);
    glFinish();
    image::Image8 image = fb.readImage8();
    gl::Framebuffer::bindDefault();
    return image;
}

}  // namespace prism::rain
