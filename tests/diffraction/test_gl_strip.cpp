// GLSL against the double-precision CPU emulation of the same tables: a strip of outgoing
// angles in the plane of incidence, rendered into RGBA32F on the headless context, for both
// paths (a: per wavelength, b: pre-integrated). Relative Linf <= 1e-3 of the strip's peak.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <glm/glm.hpp>

#include "prism/diffraction/diffraction_gl.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "diffraction_gl_support.hpp"
#include "prism/test/gl_test.hpp"

using namespace prism::diffraction;

namespace {

constexpr double kStartDeg = -80.0, kStepDeg = 0.5;
constexpr int kColumns = 321;  // -80 .. 80 deg

class DiffractionGl : public prism::test::GlTest {
  protected:
    // Renders the strip for light incidence `incidenceDeg` and returns relative Linf vs `cpu`.
    template <typename Cpu>
    static double stripError(const DiffractionTextures& textures, double incidenceDeg, Cpu cpu) {
        prism::gl::Program& program = diffractionPrograms().get("brdf_map", {{"DIFFRACTION_PATH", textures.variant()}});
        prism::gl::Framebuffer target(kColumns, 1, prism::gl::ColorFormat::Rgba32F);
        target.clear({0.0f, 0.0f, 0.0f, 0.0f});
        const Direction toLight = fromAngles(incidenceDeg, 180.0);
        program.use();
        textures.apply(program);
        program.set("u_diffractionMapAngles", glm::vec4(kStartDeg, kStepDeg, incidenceDeg, 0.0));
        GLuint vao = 0;
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glDeleteVertexArrays(1, &vao);
        prism::gl::throwIfGlError("drawing the BRDF strip");
        const prism::image::ImageF image = target.readImageF();
        double maxError = 0.0, maxValue = 0.0;
        for (int c = 0; c < kColumns; ++c) {
            const LinearRgb want = cpu(toLight, fromAngles(kStartDeg + c * kStepDeg, 0.0));
            const double wantRgb[3] = {want.r, want.g, want.b};
            for (int k = 0; k < 3; ++k) {
                const double got = image.at(c, 0)[k];
                EXPECT_TRUE(std::isfinite(got)) << c;
                maxError = std::max(maxError, std::abs(got - wantRgb[k]));
                maxValue = std::max(maxValue, std::abs(wantRgb[k]));
            }
        }
        EXPECT_GT(maxValue, 0.0);
        return maxError / maxValue;
    }
};

}  // namespace

TEST_F(DiffractionGl, PerWavelengthPathMatchesCpu) {
    const SpectralTables tables = buildSpectralTables(test::testGrating(), {.size = 128, .wavelengthStepNm = 10});
    const DiffractionTextures textures(tables);
    for (double incidence : {0.0, 30.0, 75.0}) {
        const double error =
            stripError(textures, incidence, [&](Direction l, Direction v) { return shadeSpectral(tables, l, v); });
        std::printf("path a, incidence %g: relative Linf %.3g\n", incidence, error);
        EXPECT_LE(error, 1e-3) << incidence;
    }
}

TEST_F(DiffractionGl, IntegratedPathMatchesCpu) {
    const SpectralTables spectral = buildSpectralTables(test::testGrating(), {.size = 128, .wavelengthStepNm = 10});
    const IntegratedTables tables = buildIntegratedTables(spectral);
    const DiffractionTextures textures(tables);
    for (double incidence : {0.0, 30.0, 75.0}) {
        const double error =
            stripError(textures, incidence, [&](Direction l, Direction v) { return shadeIntegrated(tables, l, v); });
        std::printf("path b, incidence %g: relative Linf %.3g\n", incidence, error);
        EXPECT_LE(error, 1e-3) << incidence;
    }
}

TEST_F(DiffractionGl, OnlyTheChosenPathIsUploaded) {
    const SpectralTables spectral = buildSpectralTables(test::testGrating(), {.size = 32, .wavelengthStepNm = 20});
    const IntegratedTables integrated = buildIntegratedTables(spectral);
    const DiffractionTextures a(spectral), b(integrated);
    EXPECT_FALSE(a.integrated());
    EXPECT_TRUE(b.integrated());
    EXPECT_EQ(a.bytes(), spectral.bytes() + spectral.wavelengths.size() * 4 * sizeof(float));
    EXPECT_EQ(b.bytes(), integrated.bytes());
}

TEST_F(DiffractionGl, VolumePathMatchesCpu) {
    const SpectralTables spectral = buildSpectralTables(test::testGrating(), {.size = 128, .wavelengthStepNm = 10});
    const VolumeTables tables = buildVolumeTables(buildIntegratedTables(spectral), 16);
    const DiffractionTextures textures(tables);
    for (double incidence : {0.0, 30.0, 75.0}) {
        const double error =
            stripError(textures, incidence, [&](Direction l, Direction v) { return shadeVolume(tables, l, v); });
        std::printf("path c, incidence %g: relative Linf %.3g\n", incidence, error);
        EXPECT_LE(error, 1e-3) << incidence;
    }
}
