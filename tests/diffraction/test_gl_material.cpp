// The diffraction material (shader_sources/diffraction/diffraction.frag) composed with the
// classic lights: the centre pixel of a plate matches the CPU emulation of the same tables
// (ambient + BRDF x light colour x cos theta_i in the tangent frame), two directional lights add
// up, and no light leaves the ambient term only.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <glm/glm.hpp>

#include "prism/diffraction/diffraction_gl.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "diffraction_gl_support.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/shaders.hpp"

using namespace prism::diffraction;

namespace {

constexpr int kSize = 65;  // odd: the centre pixel's centre is the view axis

class DiffractionMaterialGl : public prism::test::GlTest {
  protected:
    void SetUp() override {
        prism::test::GlTest::SetUp();
        if (HasFatalFailure()) return;
        camera_.eye = {0.0f, 1.0f, 1.2f};  // looks at the origin, on the plate (y = 0, normal +y)
        camera_.target = {0.0f, 0.0f, 0.0f};
        material_.color = {0.5f, 0.6f, 0.7f, 1.0f};
    }

    prism::image::ImageF render(const DiffractionTextures& textures, const prism::view::Lights& lights,
                                int directionalSlots) {
        const prism::render::GpuMesh plate(prism::geometry::makeGrid(8.0f, 8.0f, 4, 4),
                                           prism::shaders::kCatalog.contractAttributes);
        prism::gl::Framebuffer target(kSize, kSize, prism::gl::ColorFormat::Rgba32F);
        target.clear({0, 0, 0, 0});
        prism::gl::Program& program =
            diffractionPrograms().get("diffraction", {{"DIFFRACTION_PATH", textures.variant()},
                                                      {"DIRECTIONAL_LIGHTS", std::to_string(directionalSlots)},
                                                      {"POINT_LIGHTS", "0"}});
        prism::render::setFrameUniforms(program, camera_, 1.0f, lights, glm::mat4(1.0f), material_);
        program.set("u_diffractionTangent", glm::vec3(0.0f, 0.0f, 1.0f));  // grooves along x
        textures.apply(program);
        program.use();
        plate.draw();
        prism::gl::throwIfGlError("drawing the diffraction plate");
        return target.readImageF();
    }

    // World direction -> the plate's tangent frame (t = +z, n = +y, b = n x t = +x).
    static Direction tangentFrame(glm::dvec3 d) {
        d = glm::normalize(d);
        return {d.z, d.x, d.y};
    }

    prism::view::Camera camera_;
    prism::view::Material material_;
};

}  // namespace

TEST_F(DiffractionMaterialGl, CentrePixelMatchesTheCpuForBothPaths) {
    const SpectralTables spectral = buildSpectralTables(test::testGrating(), {.size = 128, .wavelengthStepNm = 10});
    const IntegratedTables integrated = buildIntegratedTables(spectral);
    prism::view::Lights lights;
    lights.ambient = glm::vec3(0.05f);
    // Light at 30 deg on the -t side; the view at 50.2 deg on the +t side sees the first order
    // of about 670 nm (sin 50.2 = sin 30 + 670 / 2500), not the mirror direction.
    const glm::vec3 lightDirection = glm::normalize(glm::vec3(0.0f, -0.866f, 0.5f));
    lights.directional.push_back({lightDirection, glm::vec3(0.9f, 0.8f, 0.7f)});
    const Direction toLight = tangentFrame(-glm::dvec3(lightDirection));
    const Direction toViewer = tangentFrame(glm::dvec3(camera_.eye - camera_.target));
    const LinearRgb brdfA = shadeSpectral(spectral, toLight, toViewer);
    const LinearRgb brdfB = shadeIntegrated(integrated, toLight, toViewer);
    ASSERT_GT(brdfA.g, 1e-3) << "the test geometry should see some diffracted light";
    for (int path = 0; path < 2; ++path) {
        const DiffractionTextures textures =
            path == 0 ? DiffractionTextures(spectral) : DiffractionTextures(integrated);
        const LinearRgb brdf = path == 0 ? brdfA : brdfB;
        const prism::image::ImageF image = render(textures, lights, 1);
        const auto pixel = image.at(kSize / 2, kSize / 2);
        const double expected[3] = {0.05 * 0.5 + brdf.r * 0.9 * toLight.z, 0.05 * 0.6 + brdf.g * 0.8 * toLight.z,
                                    0.05 * 0.7 + brdf.b * 0.7 * toLight.z};
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(pixel[c], expected[c], 2e-3 * (1.0 + expected[c])) << "path " << path << " channel " << c;
    }
}

TEST_F(DiffractionMaterialGl, DirectionalLightsAddUpAndAmbientRemains) {
    const SpectralTables spectral = buildSpectralTables(test::testGrating(), {.size = 64, .wavelengthStepNm = 20});
    const DiffractionTextures textures(buildIntegratedTables(spectral));
    prism::view::Lights none, first, second, both;
    for (prism::view::Lights* l : {&none, &first, &second, &both}) l->ambient = glm::vec3(0.05f);
    const prism::view::DirectionalLight a{glm::normalize(glm::vec3(0.0f, -0.866f, 0.5f)), glm::vec3(1.0f)};
    const prism::view::DirectionalLight b{glm::normalize(glm::vec3(-0.5f, -0.8f, 0.1f)), glm::vec3(0.2f, 0.5f, 1.0f)};
    first.directional = {a};
    second.directional = {b};
    both.directional = {a, b};
    const prism::image::ImageF imageNone = render(textures, none, 2), imageA = render(textures, first, 2),
                               imageB = render(textures, second, 2), imageBoth = render(textures, both, 2);
    double lit = 0.0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double ambient = imageNone.at(x, y)[c];
                const double sum = imageA.at(x, y)[c] + imageB.at(x, y)[c] - ambient;
                EXPECT_NEAR(imageBoth.at(x, y)[c], sum, 1e-4 * (1.0 + std::abs(sum))) << x << "," << y;
                lit = std::max(lit, imageA.at(x, y)[c] - ambient);
            }
            EXPECT_NEAR(imageNone.at(x, y)[0], 0.05 * 0.5, 1e-6);  // no light: ambient x colour
        }
    }
    EXPECT_GT(lit, 1e-3);
}
