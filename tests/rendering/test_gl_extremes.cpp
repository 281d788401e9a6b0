// Numeric extremes: each case renders every catalogue shader (unicolor, flat, smooth,
// gouraud, phong, phong BLINN=1) to RGBA32F and checks that no pixel is NaN or Inf, that
// no channel is brighter than the lights allow (brightestAllowed(), at most
// view::maxRadiance(lights, material)) or below zero, and that something was drawn (or, for a
// zero world scale, that nothing was). Cases: shininess 0, 1e-6, 1, 128, 1e4 (and 1e30);
// grazing, back-facing, touching and no lights; fog of density 0 and 3e38; zero-length,
// non-unit, scaled and non-finite normals; degenerate triangles; zero, non-uniform, huge
// and tiny world scales; extreme near/far ratios. Scale and near/far cases are also
// compared with the equivalent unit-scale scene: the image must not change. Finally the
// checks are shown to catch two bugs of the FUDGE shader thesis's Phong shader (appendix
// ShaderPhong.frag) put back into Prism's.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/image/image_compare.hpp"
#include "prism/geometry/normals.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"
#include "rendering_test_support.hpp"

namespace prism::rendering_test {
namespace {

constexpr int kSize = 64;
// Float32 rounding in the shaders (a dot product of unit vectors may come out a few ulps
// above 1) stays far below this; a real over-bright term (a constant added to the
// highlight, an unnormalised normal) is far above it.
constexpr float kBrightnessEpsilon = 1e-3f;
constexpr glm::vec4 kBackground{0.02f, 0.02f, 0.03f, 1.0f};
// Scenes that only differ by a uniform scale of everything (or by near/far) must give
// the same image; these are the golden thresholds.
constexpr image::Thresholds kSameImage{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};

enum class Expect {
    LitAndDrawn,   // covers >= minCoveredShare, and lights add visibly to the ambient term
    DrawnUnlit,    // covers >= minCoveredShare; lights may add nothing (grazing, back light)
    NothingDrawn,  // every pixel is exactly the background
};

struct Scene {
    geometry::Mesh mesh;  // as given to meshForShader (normals kept when complete)
    glm::mat4 world{1.0f};
    view::Material material{.color = {0.8f, 0.35f, 0.25f, 1.0f}, .shininess = 32.0f, .specular = 0.5f};
    view::Lights lights = render::defaultLights();
    view::Camera camera = render::defaultCamera();
    std::optional<view::Fog> fog;  // runs the shaders' FOG=1 variants
    Expect expect = Expect::LitAndDrawn;
    double minCoveredShare = 0.05;
    bool customNormals = false;  // check the mesh's own normals reach the non-flat shaders
};

Scene sphereScene() {
    Scene s;
    s.mesh = render::namedMesh("sphere", 2);
    return s;
}

std::string fmt(const glm::vec3& v) {
    std::ostringstream o;
    o << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return o.str();
}

render::RenderJob sceneJob(const ShaderSpec& spec, const Scene& scene) {
    render::RenderJob job = jobFor(spec, scene.mesh, kSize, kSize);
    job.world = scene.world;
    job.material = scene.material;
    job.lights = scene.lights;
    job.camera = scene.camera;
    job.background = kBackground;
    job.fog = scene.fog;
    return job;
}

// Renders `scene` with `spec` into `image` and checks the invariants.
void renderAndCheckShader(const ShaderSpec& spec, const Scene& scene, image::ImageF& image) {
    const render::RenderJob job = sceneJob(spec, scene);
    if (scene.customNormals && spec.shader != "flat") {
        EXPECT_EQ(job.mesh.normals.size(), scene.mesh.normals.size());
        // Bitwise, so NaN normals compare equal to themselves.
        EXPECT_TRUE(job.mesh.normals.size() == scene.mesh.normals.size() &&
                    std::memcmp(job.mesh.normals.data(), scene.mesh.normals.data(),
                                scene.mesh.normals.size() * sizeof(glm::vec3)) == 0)
            << "meshForShader replaced the test's normals";
    }

    glm::vec3 bound = brightestAllowed(spec, scene.lights, scene.material);
    if (scene.fog) bound = glm::max(bound, scene.fog->color);  // fog mixes towards its colour
    ASSERT_TRUE(kBackground.r <= bound.r && kBackground.g <= bound.g && kBackground.b <= bound.b)
        << "test setup: the background " << fmt(glm::vec3(kBackground)) << " is brighter than the bound " << fmt(bound);

    ASSERT_NO_THROW(image = render::renderImageF(programCache(), job));
    ASSERT_EQ(image.width, kSize);

    // countNonFinite is the runtime's own check (prism-render --check-finite uses it).
    EXPECT_EQ(image::countNonFinite(image), 0u) << "pixels with NaN or Inf";
    const PixelInspection px = inspectPixels(image, bound, kBrightnessEpsilon);
    EXPECT_EQ(px.overBright, 0u) << "pixels brighter than the lights allow " << fmt(bound)
                                 << "; first: " << px.firstOverBright;
    EXPECT_EQ(px.negative, 0u) << "pixels below zero; first: " << px.firstNegative;

    const std::size_t covered = coveredPixels(image, kBackground);
    const double share = static_cast<double>(covered) / static_cast<double>(image.pixelCount());
    if (scene.expect == Expect::NothingDrawn) {
        EXPECT_EQ(covered, 0u) << "expected an empty image";
    } else {
        EXPECT_GE(share, scene.minCoveredShare) << "the mesh covers too little of the image";
    }
    if (scene.expect == Expect::LitAndDrawn && spec.lit) {
        // The lights must add to the ambient term somewhere: a render whose lights
        // were lost would otherwise pass.
        const glm::vec3 ambientOnly = scene.lights.ambient * glm::vec3(scene.material.color);
        float brightest = 0.0f;
        for (std::size_t i = 0; i < image.data.size(); i += 4) brightest = std::max(brightest, image.data[i]);
        EXPECT_GT(brightest, ambientOnly.r + 0.05f) << "no pixel is lit beyond the ambient term";
    }
}

// Renders `scene` with every catalogue shader, checks the invariants, returns the images.
std::map<std::string, image::ImageF> renderAndCheck(const Scene& scene) {
    std::map<std::string, image::ImageF> images;
    for (const ShaderSpec& spec : catalogueShaders()) {
        SCOPED_TRACE("shader " + spec.label);
        renderAndCheckShader(spec, scene, images[spec.label]);
    }
    return images;
}

// Largest red channel of the pixels in columns [x0, x1) that show the mesh.
float brightestRedInColumns(const image::ImageF& image, int x0, int x1) {
    float m = 0.0f;
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) m = std::max(m, image.at(x, y)[0]);
    return m;
}

// Every shader's image of `scene` is the same as of `reference` within kSameImage.
void expectSameImages(const std::map<std::string, image::ImageF>& scene,
                      const std::map<std::string, image::ImageF>& reference) {
    for (const auto& [label, image] : scene) {
        const image::ImageComparison cmp = image::compareImages(
            image::toImage8(image), image::toImage8(reference.at(label)), kSameImage.maxChannelDiff);
        EXPECT_TRUE(image::passes(cmp, kSameImage)) << label << ": " << image::describe(cmp, kSameImage);
    }
}

class Extremes : public test::GlTest {};

// --- Shininess --------------------------------------------------------------------

TEST_F(Extremes, ShininessZero) {
    // pow(x, 0) is undefined in GLSL for x == 0 (a bug of the FUDGE shader thesis's shaders,
    // §5.3); safePow never evaluates it.
    Scene s = sphereScene();
    s.material.shininess = 0.0f;
    renderAndCheck(s);
}

TEST_F(Extremes, ShininessOneMillionth) {
    Scene s = sphereScene();
    s.material.shininess = 1e-6f;
    renderAndCheck(s);
}

TEST_F(Extremes, ShininessOne) {
    Scene s = sphereScene();
    s.material.shininess = 1.0f;
    renderAndCheck(s);
}

TEST_F(Extremes, Shininess128) {
    Scene s = sphereScene();
    s.material.shininess = 128.0f;
    renderAndCheck(s);
}

TEST_F(Extremes, Shininess1e4) {
    Scene s = sphereScene();
    s.material.shininess = 1e4f;
    renderAndCheck(s);
}

TEST_F(Extremes, Shininess1e30) {
    // prism-render accepts any finite shininess. A base that rounds a few ulps above 1
    // raised to 1e30 would be Inf unless the base is clamped to [0, 1].
    Scene s = sphereScene();
    s.material.shininess = 1e30f;
    renderAndCheck(s);
}

// --- Light directions ---------------------------------------------------------------

TEST_F(Extremes, GrazingLightPerpendicularToView) {
    // view::Camera on +Z, one light shining along +X: exactly the left half of the sphere is lit.
    Scene s = sphereScene();
    s.camera.eye = {0.0f, 0.0f, 3.2f};
    s.lights.directional = {{.direction = {1.0f, 0.0f, 0.0f}, .color = glm::vec3(1.0f)}};
    const auto images = renderAndCheck(s);
    const float ambientRed = s.lights.ambient.r * s.material.color.r;
    for (const auto& spec : catalogueShaders()) {
        if (!spec.lit) continue;
        const image::ImageF& image = images.at(spec.label);
        // Right of the centre (beyond one triangle's width) the surface faces away from the light.
        EXPECT_LE(brightestRedInColumns(image, kSize / 2 + 6, kSize), ambientRed + kBrightnessEpsilon) << spec.label;
        EXPECT_GT(brightestRedInColumns(image, 0, kSize / 2 - 6), ambientRed + 0.2f) << spec.label;
    }
}

TEST_F(Extremes, GrazingLightParallelToSurface) {
    // A grid facing +Y lit along +X: the light only grazes it, so it adds (almost) nothing.
    Scene s;
    s.mesh = render::namedMesh("grid", 2);
    s.lights.directional = {{.direction = {1.0f, 0.0f, 0.0f}, .color = glm::vec3(1.0f)}};
    s.expect = Expect::DrawnUnlit;
    const auto images = renderAndCheck(s);
    const float ambientRed = s.lights.ambient.r * s.material.color.r;
    for (const auto& spec : catalogueShaders()) {
        if (!spec.lit) continue;
        EXPECT_LE(brightestRedInColumns(images.at(spec.label), 0, kSize), ambientRed + 0.01f) << spec.label;
    }
}

TEST_F(Extremes, BackFacingLight) {
    // The only light shines from behind the sphere towards the camera: every visible
    // point faces away from it, so only the ambient term remains (no specular either).
    Scene s = sphereScene();
    const view::Camera cam = s.camera;
    s.lights.directional = {{.direction = glm::normalize(cam.eye - cam.target), .color = glm::vec3(1.0f)}};
    s.expect = Expect::DrawnUnlit;
    const auto images = renderAndCheck(s);
    const glm::vec3 ambient = s.lights.ambient * glm::vec3(s.material.color);
    for (const auto& spec : catalogueShaders()) {
        if (!spec.lit) continue;
        const image::ImageF& image = images.at(spec.label);
        for (std::size_t i = 0; i < image.data.size(); i += 4)
            for (int c = 0; c < 3; ++c)
                ASSERT_LE(image.data[i + static_cast<std::size_t>(c)], ambient[c] + kBrightnessEpsilon)
                    << spec.label << " lit a surface facing away from the light";
    }
}

TEST_F(Extremes, PointLightTouchingTheSurface) {
    // The light sits exactly on the front vertex: the direction to it is a zero vector there.
    Scene s = sphereScene();
    s.mesh = render::namedMesh("icosphere", 2);  // the light goes onto its front-most vertex
    glm::vec3 front = s.mesh.positions.front();
    for (const auto& p : s.mesh.positions)
        if (p.z > front.z) front = p;
    s.lights.points = {{.position = front, .color = glm::vec3(0.9f)}};
    renderAndCheck(s);
}

TEST_F(Extremes, PointLightInsideClosedMesh) {
    Scene s = sphereScene();
    s.lights.directional.clear();
    s.lights.points = {{.position = glm::vec3(0.0f), .color = glm::vec3(1.0f)}};
    s.expect = Expect::DrawnUnlit;
    const auto images = renderAndCheck(s);
    const float ambientRed = s.lights.ambient.r * s.material.color.r;
    for (const auto& spec : catalogueShaders()) {
        if (!spec.lit) continue;
        EXPECT_LE(brightestRedInColumns(images.at(spec.label), 0, kSize), ambientRed + kBrightnessEpsilon)
            << spec.label;
    }
}

TEST_F(Extremes, AmbientLightOnly) {
    // No directional or point light at all (the zero-light variants): ambient * colour.
    Scene s = sphereScene();
    s.lights.directional.clear();
    s.lights.points.clear();
    s.expect = Expect::DrawnUnlit;
    const auto images = renderAndCheck(s);
    const float ambientRed = s.lights.ambient.r * s.material.color.r;
    for (const auto& spec : catalogueShaders()) {
        if (!spec.lit) continue;
        EXPECT_NEAR(brightestRedInColumns(images.at(spec.label), 0, kSize), ambientRed, kBrightnessEpsilon)
            << spec.label;
    }
}

// --- Fog (the FOG=1 variants) ---------------------------------------------------------

TEST_F(Extremes, FogDensityZero) {
    Scene s = sphereScene();
    s.fog = view::Fog{.color = {0.62f, 0.66f, 0.72f}, .density = 0.0f};
    renderAndCheck(s);
}

TEST_F(Extremes, FogDensityHuge) {
    // Every fragment is fully fogged: the surface takes the fog colour, never NaN from exp().
    Scene s = sphereScene();
    s.fog = view::Fog{.color = {0.62f, 0.66f, 0.72f}, .density = 3e38f};
    s.expect = Expect::DrawnUnlit;
    const auto images = renderAndCheck(s);
    for (const auto& [label, image] : images) {
        const image::RgbaF centre = image.at(kSize / 2, kSize / 2);
        EXPECT_NEAR(centre[0], 0.62f, 2e-3f) << label;
        EXPECT_NEAR(centre[2], 0.72f, 2e-3f) << label;
    }
}

// --- Normals ------------------------------------------------------------------------

Scene sphereWithNormals(const std::function<glm::vec3(std::size_t, const glm::vec3&)>& normalOf) {
    Scene s = sphereScene();
    for (std::size_t i = 0; i < s.mesh.normals.size(); ++i) s.mesh.normals[i] = normalOf(i, s.mesh.normals[i]);
    s.customNormals = true;
    return s;
}

TEST_F(Extremes, ZeroLengthNormals) {
    Scene s = sphereWithNormals([](std::size_t, const glm::vec3&) { return glm::vec3(0.0f); });
    renderAndCheck(s);
}

TEST_F(Extremes, NonUnitNormals) {
    // Lengths from 0.01 to 100 on neighbouring vertices: interpolation skews, lighting must not brighten.
    constexpr float kLengths[] = {0.01f, 0.5f, 2.0f, 10.0f, 100.0f};
    Scene s = sphereWithNormals([&](std::size_t i, const glm::vec3& n) { return n * kLengths[i % 5]; });
    renderAndCheck(s);
}

TEST_F(Extremes, NormalsScaledBy1e6) {
    Scene s = sphereWithNormals([](std::size_t, const glm::vec3& n) { return n * 1e6f; });
    renderAndCheck(s);
}

TEST_F(Extremes, NormalsScaledBy1em6) {
    Scene s = sphereWithNormals([](std::size_t, const glm::vec3& n) { return n * 1e-6f; });
    renderAndCheck(s);
}

TEST_F(Extremes, NonFiniteNormals) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Scene s = sphereWithNormals([&](std::size_t i, const glm::vec3& n) {
        return i % 3 == 0 ? glm::vec3(nan, 0.0f, 1.0f) : i % 3 == 1 ? glm::vec3(inf, -inf, 0.0f) : n;
    });
    renderAndCheck(s);
}

// --- Degenerate triangles -----------------------------------------------------------

TEST_F(Extremes, DegenerateTriangles) {
    Scene s = sphereScene();
    geometry::Mesh& m = s.mesh;
    m.normals.clear();  // computed by meshForShader, through the degenerate-triangle rules
    m.uvs.clear();
    const auto add = [&](glm::vec3 p) {
        m.positions.push_back(p);
        return static_cast<std::uint32_t>(m.positions.size() - 1);
    };
    // Zero area: three corners at one point, in front of the sphere.
    const std::uint32_t a = add({0.3f, 0.2f, 1.2f}), b = add({0.3f, 0.2f, 1.2f}), c = add({0.3f, 0.2f, 1.2f});
    m.indices.insert(m.indices.end(), {a, b, c});
    // A repeated index, on the sphere's own vertices.
    m.indices.insert(m.indices.end(), {0u, 0u, 5u});
    m.indices.insert(m.indices.end(), {7u, 9u, 7u});
    // Collinear corners, exactly and nearly (a sliver of area ~1e-9).
    const std::uint32_t l0 = add({-0.5f, 0.0f, 1.1f}), l1 = add({0.0f, 0.0f, 1.1f}), l2 = add({0.5f, 0.0f, 1.1f});
    m.indices.insert(m.indices.end(), {l0, l1, l2});
    const std::uint32_t s0 = add({-0.5f, -0.3f, 1.1f}), s1 = add({0.0f, -0.3f + 2e-9f, 1.1f}),
                        s2 = add({0.5f, -0.3f, 1.1f});
    m.indices.insert(m.indices.end(), {s0, s1, s2});

    geometry::Mesh withNormals = render::meshForShader("phong", m);
    for (const auto& n : withNormals.normals) {
        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    }
    renderAndCheck(s);
}

// --- World scales -------------------------------------------------------------------

TEST_F(Extremes, ZeroWorldScale) {
    // Every vertex lands on the origin: nothing is drawn, and the normal matrix of a
    // singular world matrix must not poison anything with NaN.
    Scene s = sphereScene();
    s.world = glm::scale(glm::mat4(1.0f), glm::vec3(0.0f));
    s.expect = Expect::NothingDrawn;
    renderAndCheck(s);
}

TEST_F(Extremes, NonUniformWorldScale) {
    Scene s = sphereScene();
    s.world = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1e3f, 1e-3f));
    renderAndCheck(s);
}

// Everything (mesh and camera) scaled by `k`: directional lighting is scale-free, so the
// images must match the unit-scale ones.
Scene scaledScene(float k) {
    Scene s = sphereScene();
    s.world = glm::scale(glm::mat4(1.0f), glm::vec3(k));
    s.camera.eye *= k;
    s.camera.target *= k;
    s.camera.nearPlane *= k;
    s.camera.farPlane *= k;
    return s;
}

TEST_F(Extremes, HugeWorldScale1e6) {
    const auto huge = renderAndCheck(scaledScene(1e6f));
    const auto unit = renderAndCheck(scaledScene(1.0f));
    expectSameImages(huge, unit);
}

TEST_F(Extremes, TinyWorldScale1em6) {
    const auto tiny = renderAndCheck(scaledScene(1e-6f));
    const auto unit = renderAndCheck(scaledScene(1.0f));
    expectSameImages(tiny, unit);
}

// --- Near/far ratios ----------------------------------------------------------------

TEST_F(Extremes, NearFarRatio1e8) {
    // near 1e-4, far 1e4: depth precision is thin but the tilted torus must still
    // occlude itself exactly as with the default near 0.1, far 50.
    Scene s = sphereScene();
    s.mesh = render::namedMesh("torus", 2);  // self-occluding
    s.world = glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(1, 0, 0));
    Scene reference = s;
    s.camera.nearPlane = 1e-4f;
    s.camera.farPlane = 1e4f;
    expectSameImages(renderAndCheck(s), renderAndCheck(reference));
}

TEST_F(Extremes, NearPlane1e3FarPlane1e4MeshFarAway) {
    // The mesh sits 5000 units away, scaled 1500x, viewed with near 1e3 and far 1e4; the
    // same scene divided by 1500 is the reference.
    constexpr float kDistance = 5000.0f, kScale = 1500.0f;
    Scene s = sphereScene();
    s.mesh = render::namedMesh("torus", 2);
    const glm::mat4 tilt = glm::rotate(glm::mat4(1.0f), glm::radians(60.0f), glm::vec3(1, 0, 0));
    s.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance)) *
              glm::scale(glm::mat4(1.0f), glm::vec3(kScale)) * tilt;
    s.camera.eye = {0.0f, 0.0f, 0.0f};
    s.camera.target = {0.0f, 0.0f, -kDistance};
    s.camera.nearPlane = 1e3f;
    s.camera.farPlane = 1e4f;

    Scene reference = s;
    reference.world = tilt;
    reference.camera.eye = {0.0f, 0.0f, kDistance / kScale};
    reference.camera.target = {0.0f, 0.0f, 0.0f};
    reference.camera.nearPlane = 1e3f / kScale;
    reference.camera.farPlane = 1e4f / kScale;
    expectSameImages(renderAndCheck(s), renderAndCheck(reference));
}

// --- The checks above catch the bugs of the FUDGE shader thesis's shaders ---------------
// A copy of one catalogue shader, every variant, with text replaced in its stages, as
// its own one-shader catalogue: the thesis's bugs put back into the current shaders.
class MutantCatalog {
  public:
    MutantCatalog(std::string_view shaderName, const std::vector<std::pair<std::string, std::string>>& replacements) {
        const catalog::Shader* original = catalog::findShader(shaders::kCatalog, shaderName);
        if (!original) throw std::invalid_argument("no catalogue shader " + std::string(shaderName));
        std::size_t stageCount = 0;
        for (const auto& v : original->variants) stageCount += v.stages.size();
        // Reserved up front: the spans below point into these vectors.
        sources_.reserve(stageCount);
        chunks_.reserve(stageCount);
        stages_.reserve(stageCount);
        std::vector<bool> found(replacements.size(), false);
        for (const auto& v : original->variants) {
            const std::size_t first = stages_.size();
            for (const auto& stage : v.stages) {
                std::string text = catalog::joinChunks(stage.chunks);
                for (std::size_t r = 0; r < replacements.size(); ++r) {
                    const auto& [from, to] = replacements[r];
                    for (std::size_t at = text.find(from); at != std::string::npos;
                         at = text.find(from, at + to.size())) {
                        text.replace(at, from.size(), to);
                        found[r] = true;
                    }
                }
                sources_.push_back(std::move(text));
                chunks_.push_back(sources_.back());
                catalog::StageSource mutated = stage;
                mutated.chunks = std::span<const std::string_view>(&chunks_.back(), 1);
                stages_.push_back(mutated);
            }
            catalog::Variant mutated = v;
            mutated.stages = std::span<const catalog::StageSource>(stages_.data() + first, v.stages.size());
            variants_.push_back(mutated);
        }
        for (std::size_t r = 0; r < replacements.size(); ++r)
            if (!found[r])
                throw std::invalid_argument("mutation: '" + replacements[r].first + "' is not in " +
                                            std::string(shaderName) + "; update the test to the current shader text");
        shader_ = *original;
        shader_.variants = variants_;
        catalog_ = shaders::kCatalog;
        catalog_.shaders = std::span<const catalog::Shader>(&shader_, 1);
    }
    MutantCatalog(const MutantCatalog&) = delete;  // spans point into the members
    MutantCatalog& operator=(const MutantCatalog&) = delete;

    const catalog::Catalog& catalog() const { return catalog_; }

  private:
    std::vector<std::string> sources_;
    std::vector<std::string_view> chunks_;
    std::vector<catalog::StageSource> stages_;
    std::vector<catalog::Variant> variants_;
    catalog::Shader shader_{};
    catalog::Catalog catalog_{};
};

PixelInspection renderMutant(const MutantCatalog& mutant, const Scene& scene) {
    render::ProgramCache cache(mutant.catalog());
    const ShaderSpec& spec = shaderSpec("phong");
    const image::ImageF image = render::renderImageF(cache, sceneJob(spec, scene));
    EXPECT_GE(coveredPixels(image, kBackground), image.pixelCount() / 20) << "the mutant drew (almost) nothing";
    return inspectPixels(image, brightestAllowed(spec, scene.lights, scene.material), kBrightnessEpsilon);
}

class ExtremeChecksCatchThesisShaderBugs : public test::GlTest {};

TEST_F(ExtremeChecksCatchThesisShaderBugs, ConstantAddedToHighlightIsOverBright) {
    // calculateReflection (FUDGE shader thesis §5.3) added 1 to the highlight.
    const MutantCatalog mutant("phong", {{"return safePow(max(dot(r, toEye), 0.0), shininess);",
                                          "return safePow(max(dot(r, toEye), 0.0), shininess) + 1.0;"}});
    const PixelInspection px = renderMutant(mutant, sphereScene());
    EXPECT_GT(px.overBright, 0u);
    std::cout << "[thesis shader bug] highlight + 1: " << px.overBright << " over-bright pixels, first "
              << px.firstOverBright << "\n";
}

// The thesis shaders' pow(0, 0) (shininess 0 by default, §5.3) is undefined in GLSL, but llvmpipe
// returns a finite value for it, so no pixel check can show it on this driver; the
// ShininessZero case above still guards safePow on drivers that return NaN.

TEST_F(ExtremeChecksCatchThesisShaderBugs, NormalizeOfZeroNormalIsNonFinite) {
    const MutantCatalog mutant(
        "phong", {{"vec3 n = safeNormalize(v_eyeNormal, vec3(0.0, 0.0, 1.0));", "vec3 n = normalize(v_eyeNormal);"}});
    Scene s = sphereWithNormals([](std::size_t, const glm::vec3&) { return glm::vec3(0.0f); });
    const PixelInspection px = renderMutant(mutant, s);
    EXPECT_GT(px.nonFinite, 0u);
    std::cout << "[thesis shader bug] normalize(0): " << px.nonFinite << " non-finite pixels\n";
}

}  // namespace
}  // namespace prism::rendering_test
