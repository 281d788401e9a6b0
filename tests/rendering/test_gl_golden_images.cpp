// Golden-image tests: every catalogue shader (unicolor, flat, smooth, gouraud, phong,
// phong with BLINN=1) on several meshes, lights and shininess values, rendered at
// 128x128 on llvmpipe and compared with tests/golden/<shader>/<case>.png; plus mutation
// tests showing the comparison catches a changed shininess, a moved light and
// Gouraud-instead-of-Phong.
//
// The check, its update mode (the tests then report SKIPPED, never "passed") and where
// actual and diff images go (default: <build>/tests/rendering/golden-failures):
// prism/test/golden.hpp, the one golden check of Prism's tests.
//
// Thresholds (also in tests/golden/README.md): a pixel is "over" when a channel differs
// by more than 3/255; a case passes with at most 0.1 % of pixels over and a mean
// absolute error of at most 0.5/255. llvmpipe renders byte-identically run to run (the
// test RepeatedRenderIsByteIdentical checks that), so any difference at all is a real
// change; the few /255 only absorb driver or technique changes, which docs/references.md
// ("Golden-image testing") records at up to 2/255 on some pixels.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"
#include "prism/test/golden.hpp"
#include "prism/test/gl_test.hpp"
#include "rendering_test_support.hpp"

namespace prism::rendering_test {

namespace {

namespace fs = std::filesystem;

constexpr int kGoldenSize = 128;
constexpr image::Thresholds kGoldenThresholds{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};

// A key light by where it shines from; the fill light of render::defaultLights() stays.
struct NamedLight {
    const char* name;
    glm::vec3 direction;  // from the light into the scene, world space
};
// Named by where the light is as seen from the camera (it shines the opposite way).
constexpr NamedLight kLightUpperLeft{"upper-left", {0.5f, -0.6f, -0.65f}};
constexpr NamedLight kLightUpperRight{"upper-right", {-0.5f, -0.6f, -0.65f}};  // render::defaultLights()' key light
constexpr NamedLight kLightRight{"right", {-1.0f, -0.15f, -0.35f}};
constexpr NamedLight kLightFrontAbove{"front-above", {0.0f, -0.45f, -1.0f}};

struct NamedColor {
    const char* name;
    glm::vec4 rgba;
};
constexpr NamedColor kTerracotta{"terracotta", {0.8f, 0.35f, 0.25f, 1.0f}};
constexpr NamedColor kTeal{"teal", {0.15f, 0.6f, 0.55f, 1.0f}};
constexpr NamedColor kGrey{"grey", {0.7f, 0.7f, 0.7f, 1.0f}};

struct GoldenCase {
    std::string shaderLabel;  // see catalogueShaders()
    std::string mesh;         // a prism::render::namedMesh name
    unsigned subdivision = 2;
    float tiltDegrees = 0.0f;  // rotation about X, to show a torus's hole
    float shininess = 32.0f;
    NamedLight light = kLightUpperLeft;
    NamedColor color = kTerracotta;

    // Self-describing: only what changes the image for this shader is in the name.
    std::string name() const {
        const ShaderSpec& spec = shaderSpec(shaderLabel);
        std::ostringstream n;
        n << mesh;
        if (mesh != "trefoil" && mesh != "cube") n << "-subdiv" << subdivision;  // the others ignore it
        if (tiltDegrees != 0.0f) n << "-tilt" << tiltDegrees;
        if (!spec.lit) {
            n << "-color-" << color.name;
        } else {
            if (spec.specular) n << "-shininess" << shininess;
            n << "-light-" << light.name;
            if (std::string_view(color.name) != kTerracotta.name) n << "-color-" << color.name;
        }
        return n.str();
    }
    fs::path goldenPath() const { return fs::path(PRISM_GOLDEN_DIR) / shaderLabel / (name() + ".png"); }
};

// gtest prints the case by its golden path, not as bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) {
    *os << c.shaderLabel << "/" << c.name();
}

std::vector<GoldenCase> goldenCases() {
    std::vector<GoldenCase> cases;
    cases.push_back({"unicolor", "sphere", 2, 0.0f, 32.0f, kLightUpperLeft, kTerracotta});
    cases.push_back({"unicolor", "torus", 2, 60.0f, 32.0f, kLightUpperLeft, kTeal});
    cases.push_back({"unicolor", "icosphere", 1, 0.0f, 32.0f, kLightUpperLeft, kGrey});
    for (const char* label : {"flat", "smooth"}) {
        cases.push_back({label, "sphere", 2, 0.0f, 32.0f, kLightUpperLeft, kTerracotta});
        cases.push_back({label, "torus", 2, 60.0f, 32.0f, kLightRight, kTerracotta});
        cases.push_back({label, "icosphere", 1, 0.0f, 32.0f, kLightFrontAbove, kTeal});
    }
    for (const char* label : {"gouraud", "phong", "phong-blinn"}) {
        cases.push_back({label, "sphere", 2, 0.0f, 32.0f, kLightUpperLeft, kTerracotta});
        cases.push_back({label, "torus", 2, 60.0f, 8.0f, kLightRight, kTerracotta});
        cases.push_back({label, "icosphere", 1, 0.0f, 128.0f, kLightFrontAbove, kTeal});
    }
    cases.push_back({"phong", "trefoil", 0, 0.0f, 64.0f, kLightUpperRight, kGrey});
    return cases;
}

image::Image8 renderGoldenCase(const GoldenCase& c) {
    const ShaderSpec& spec = shaderSpec(c.shaderLabel);
    render::RenderJob job = jobFor(spec, render::namedMesh(c.mesh, c.subdivision), kGoldenSize, kGoldenSize);
    job.world = glm::rotate(glm::mat4(1.0f), glm::radians(c.tiltDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
    job.material.color = c.color.rgba;
    job.material.shininess = c.shininess;
    job.material.specular = 0.5f;
    job.lights.directional.at(0).direction = c.light.direction;
    return render::renderImage8(programCache(), job);
}

std::string testNameOf(const ::testing::TestParamInfo<GoldenCase>& info) {
    std::string n = info.param.shaderLabel + "_" + info.param.name();
    for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return n;
}

class GoldenImage : public test::GlTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(GoldenImage, MatchesStoredGoldenWithinThresholds) {
    const GoldenCase& c = GetParam();
    const image::Image8 actual = renderGoldenCase(c);
    ASSERT_EQ(actual.width, kGoldenSize);
    // A blank render must never become a golden: the mesh covers a good part of the frame.
    ASSERT_GT(coveredPixels(actual, render::RenderJob{}.background), actual.pixelCount() / 10)
        << c.name() << " drew (almost) nothing";

    test::expectMatchesGolden(actual, {.golden = c.goldenPath(),
                                       .outName = c.shaderLabel + "/" + c.name(),
                                       .thresholds = kGoldenThresholds,
                                       .outDir = PRISM_GOLDEN_FAILURE_DIR});
}

INSTANTIATE_TEST_SUITE_P(Catalogue, GoldenImage, ::testing::ValuesIn(goldenCases()), testNameOf);

// Every catalogue shader has at least three golden cases.
TEST(GoldenCatalogue, EveryShaderHasAtLeastThreeCases) {
    for (const auto& spec : catalogueShaders()) {
        int n = 0;
        for (const auto& c : goldenCases()) n += c.shaderLabel == spec.label ? 1 : 0;
        EXPECT_GE(n, 3) << spec.label;
    }
}

// Every shader of the generated catalogue is covered here: a new catalogue shader
// without goldens fails this test instead of going untested.
TEST(GoldenCatalogue, EveryCatalogueShaderIsCovered) {
    for (const auto& shader : shaders::kCatalog.shaders) {
        bool covered = false;
        for (const auto& spec : catalogueShaders()) covered = covered || spec.shader == shader.name;
        EXPECT_TRUE(covered) << "catalogue shader '" << shader.name << "' has no golden images";
    }
}

// --- Mutation tests: the comparison must catch real changes ------------------------

class GoldenMutation : public test::GlTest {
  protected:
    void SetUp() override {
        test::GlTest::SetUp();
        if (HasFatalFailure()) return;
        if (test::updatingGoldens()) GTEST_SKIP() << "goldens are being rewritten";
    }

    // The stored golden of `c`, after checking the unmutated rendering still passes
    // against it (so a failing mutant is due to the mutation, not a stale golden).
    image::Image8 goldenThatPasses(const GoldenCase& c) {
        const image::Image8 golden = image::readPng(c.goldenPath());
        const image::ImageComparison base =
            image::compareImages(renderGoldenCase(c), golden, kGoldenThresholds.maxChannelDiff);
        EXPECT_TRUE(image::passes(base, kGoldenThresholds)) << "baseline " << image::describe(base, kGoldenThresholds);
        return golden;
    }

    // Prints the statistics (the evidence) and returns whether it passed.
    static bool reportMutant(const std::string& what, const image::ImageComparison& cmp) {
        const std::string line = image::describe(cmp, kGoldenThresholds);
        std::cout << "[mutation] " << what << ": " << line << "\n";
        ::testing::Test::RecordProperty("mutation", what + ": " + line);
        return image::passes(cmp, kGoldenThresholds);
    }

    static GoldenCase phongSphere() { return {"phong", "sphere", 2, 0.0f, 32.0f, kLightUpperLeft, kTerracotta}; }
};

TEST_F(GoldenMutation, PhongShininess32RenderedAt40FailsAgainstGolden) {
    const GoldenCase original = phongSphere();
    const image::Image8 golden = goldenThatPasses(original);
    GoldenCase mutant = original;
    mutant.shininess = 40.0f;
    const image::ImageComparison cmp =
        image::compareImages(renderGoldenCase(mutant), golden, kGoldenThresholds.maxChannelDiff);
    EXPECT_FALSE(reportMutant("phong sphere shininess 32 -> 40", cmp));
}

TEST_F(GoldenMutation, PhongLightMovedFromUpperLeftToUpperRightFailsAgainstGolden) {
    const GoldenCase original = phongSphere();
    const image::Image8 golden = goldenThatPasses(original);
    GoldenCase mutant = original;
    mutant.light = kLightUpperRight;
    const image::ImageComparison cmp =
        image::compareImages(renderGoldenCase(mutant), golden, kGoldenThresholds.maxChannelDiff);
    EXPECT_FALSE(reportMutant("phong sphere light upper-left -> upper-right", cmp));
}

TEST_F(GoldenMutation, PhongLightTurnedByFiveDegreesFailsAgainstGolden) {
    // A small change, to show the thresholds are tight: the key light turned 5 degrees
    // about the vertical axis.
    const GoldenCase original = phongSphere();
    const image::Image8 golden = goldenThatPasses(original);
    GoldenCase mutant = original;
    mutant.light.direction = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(5.0f), glm::vec3(0, 1, 0)) *
                                       glm::vec4(original.light.direction, 0.0f));
    const image::ImageComparison cmp =
        image::compareImages(renderGoldenCase(mutant), golden, kGoldenThresholds.maxChannelDiff);
    EXPECT_FALSE(reportMutant("phong sphere key light turned 5 degrees", cmp));
}

TEST_F(GoldenMutation, GouraudDiffersFromPhongGoldenBeyondThresholds) {
    for (const GoldenCase& phong :
         {phongSphere(), GoldenCase{"phong", "icosphere", 1, 0.0f, 128.0f, kLightFrontAbove, kTeal}}) {
        const image::Image8 golden = goldenThatPasses(phong);
        GoldenCase gouraud = phong;
        gouraud.shaderLabel = "gouraud";
        const image::ImageComparison cmp =
            image::compareImages(renderGoldenCase(gouraud), golden, kGoldenThresholds.maxChannelDiff);
        EXPECT_FALSE(reportMutant("gouraud instead of phong, " + phong.name(), cmp));
    }
}

TEST_F(GoldenMutation, BlinnDiffersFromPhongGoldenBeyondThresholds) {
    const GoldenCase phong = phongSphere();
    const image::Image8 golden = goldenThatPasses(phong);
    GoldenCase blinn = phong;
    blinn.shaderLabel = "phong-blinn";
    const image::ImageComparison cmp =
        image::compareImages(renderGoldenCase(blinn), golden, kGoldenThresholds.maxChannelDiff);
    EXPECT_FALSE(reportMutant("phong BLINN=1 instead of BLINN=0, " + phong.name(), cmp));
}

// The premise of the thresholds: llvmpipe gives the same bytes on every repeat.
TEST_F(GoldenMutation, RepeatedRenderIsByteIdentical) {
    const GoldenCase c{"phong", "torus", 2, 60.0f, 8.0f, kLightRight, kTerracotta};
    const image::Image8 first = renderGoldenCase(c);
    const image::Image8 second = renderGoldenCase(c);
    const image::ImageComparison cmp = image::compareImages(second, first, 0);
    EXPECT_EQ(cmp.maxChannelDiff, 0) << image::describe(cmp, kGoldenThresholds);
    EXPECT_TRUE(first == second);
}

}  // namespace
}  // namespace prism::rendering_test
