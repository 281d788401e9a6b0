// Tests of the prism-render command line, run as a real process (the path comes from
// CMake as PRISM_RENDER_EXECUTABLE): bad shader names, unreadable and malformed OBJ
// files and bad numbers must exit non-zero with a message and write no image;
// --check-finite and a normal render must succeed, the latter with a PNG of the
// requested size.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/shaders.hpp"
#include "prism/test/golden.hpp"
#include "prism/test/run_command.hpp"
#include "rendering_test_support.hpp"

namespace prism::rendering_test {
namespace {

namespace fs = std::filesystem;

constexpr int kExitBadInput = 2;

std::string readText(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A fresh, empty directory for the current test.
fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path dir = fs::path(PRISM_RENDERING_TEMP_DIR) / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

test::CommandResult runPrismRender(const std::vector<std::string>& args, const fs::path& dir) {
    std::vector<std::string> command{PRISM_RENDER_EXECUTABLE};
    command.insert(command.end(), args.begin(), args.end());
    return test::runCommand(command, {.workDir = dir, .mergeStderr = false});
}

fs::path writeFile(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

// Files in `dir` other than the captured stderr: a failed run must leave none.
std::vector<std::string> imagesIn(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().extension() == ".png" || e.path().string().find(".png.tmp") != std::string::npos)
            found.push_back(e.path().string());
    return found;
}

TEST(PrismRenderCli, UnknownShaderExitsNonZeroListsKnownShadersWritesNothing) {
    const fs::path dir = testDir();
    const auto r = runPrismRender({"--shader", "phongg", "--size", "32x32", "--out", (dir / "out.png").string()}, dir);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(r.exitCode, kExitBadInput);
    EXPECT_NE(r.err.find("phongg"), std::string::npos) << r.err;
    for (const auto& s : shaders::kCatalog.shaders)
        EXPECT_NE(r.err.find(std::string(s.name)), std::string::npos)
            << "known shader " << s.name << " not listed: " << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

TEST(PrismRenderCli, UnknownVariantExitsWithBadInputWritesNothing) {
    const fs::path dir = testDir();
    const auto r = runPrismRender(
        {"--shader", "phong", "--variant", "BLINN=7", "--size", "32x32", "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find("BLINN"), std::string::npos) << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

TEST(PrismRenderCli, MissingObjFileNamesTheFileWritesNothing) {
    const fs::path dir = testDir();
    const fs::path obj = dir / "no-such-mesh.obj";
    const auto r =
        runPrismRender({"--shader", "phong", "--mesh", obj.string(), "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(obj.string()), std::string::npos) << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

TEST(PrismRenderCli, ObjPathThatIsADirectoryNamesTheFileWritesNothing) {
    // Unreadable even for root (which file permissions do not stop).
    const fs::path dir = testDir();
    const fs::path obj = dir / "folder.obj";
    fs::create_directories(obj);
    const auto r =
        runPrismRender({"--shader", "phong", "--mesh", obj.string(), "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(obj.string()), std::string::npos) << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

TEST(PrismRenderCli, ObjFaceIndexOutOfRangeNamesFileAndLineWritesNothing) {
    const fs::path dir = testDir();
    const fs::path obj = writeFile(dir / "bad-face.obj",
                                   "# a triangle that points past the vertex list\n"
                                   "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    const auto r =
        runPrismRender({"--shader", "phong", "--mesh", obj.string(), "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(obj.string() + ":5"), std::string::npos) << "expected file:line " << obj << ":5 in: " << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

TEST(PrismRenderCli, ObjVertexWithNonNumberNamesFileAndLineWritesNothing) {
    const fs::path dir = testDir();
    const fs::path obj = writeFile(dir / "bad-vertex.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n");
    const auto r =
        runPrismRender({"--shader", "phong", "--mesh", obj.string(), "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(obj.string() + ":2"), std::string::npos) << "expected file:line " << obj << ":2 in: " << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

// --- Bad numbers: exit 2, a message naming the option, no image ---------------------

struct BadNumber {
    std::string option, value, testName;
};

class PrismRenderCliBadNumber : public ::testing::TestWithParam<BadNumber> {};

TEST_P(PrismRenderCliBadNumber, ExitsWithBadInputNamesOptionWritesNothing) {
    const BadNumber& p = GetParam();
    const fs::path dir = testDir();
    const auto r = runPrismRender(
        {"--shader", "phong", "--subdiv", "0", p.option, p.value, "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(p.option), std::string::npos) << "message should name " << p.option << ": " << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

INSTANTIATE_TEST_SUITE_P(Options, PrismRenderCliBadNumber,
                         ::testing::Values(BadNumber{"--shininess", "abc", "ShininessNotANumber"},
                                           BadNumber{"--shininess", "-1", "ShininessNegative"},
                                           BadNumber{"--shininess", "inf", "ShininessInfinite"},
                                           BadNumber{"--light-dir", "1,2", "LightDirTwoComponents"},
                                           BadNumber{"--light-dir", "1,nan,2", "LightDirNaN"},
                                           BadNumber{"--size", "0x5", "SizeZeroWidth"},
                                           BadNumber{"--size", "64", "SizeWithoutHeight"}),
                         [](const ::testing::TestParamInfo<BadNumber>& info) { return info.param.testName; });

// --- Successful runs -----------------------------------------------------------------

TEST(PrismRenderCli, CheckFiniteOnNormalRenderExitsZero) {
    const fs::path dir = testDir();
    const auto r = runPrismRender(
        {"--shader", "phong", "--mesh", "sphere", "--subdiv", "1", "--size", "48x48", "--check-finite"}, dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("finite"), std::string::npos) << r.out;
    EXPECT_TRUE(imagesIn(dir).empty()) << "--check-finite without --out writes no image";
}

TEST(PrismRenderCli, SuccessfulRenderWritesPngOfRequestedSize) {
    const fs::path dir = testDir();
    const fs::path out = dir / "phong-blinn.png";
    const auto r =
        runPrismRender({"--shader", "phong", "--variant", "BLINN=1", "--mesh", "torus", "--subdiv", "1", "--shininess",
                        "64", "--light-dir", "-1,-1,-1", "--size", "96x64", "--out", out.string()},
                       dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(fs::exists(out));
    const image::Image8 image = image::readPng(out);
    EXPECT_EQ(image.width, 96);
    EXPECT_EQ(image.height, 64);
    EXPECT_GT(coveredPixels(image, render::RenderJob{}.background), image.pixelCount() / 20)
        << "the image is (almost) blank";
}

TEST(PrismRenderCli, CheckFiniteWithOutWritesPng) {
    const fs::path dir = testDir();
    const fs::path out = dir / "gouraud.png";
    const auto r = runPrismRender({"--shader", "gouraud", "--mesh", "icosphere", "--subdiv", "1", "--size", "40x30",
                                   "--check-finite", "--out", out.string()},
                                  dir);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const image::Image8 image = image::readPng(out);
    EXPECT_EQ(image.width, 40);
    EXPECT_EQ(image.height, 30);
}

// --- Stochastic scenes: --spp, --sampler, --frame, --frames -----------------------------

const std::string kSoftShadows = std::string(PRISM_SCENES_DIR) + "/soft_shadows.json";
const image::Thresholds kStochasticThresholds{3, 0.001, 0.5};  // as the scene goldens

// The scene goldens of tests/scenes, through the tests' one golden check (compare only).
test::GoldenOutcome againstSceneGolden(const image::Image8& image, const std::string& sampler) {
    const fs::path golden = fs::path(PRISM_GOLDEN_DIR) / "scenes" / ("soft_shadows_" + sampler + ".png");
    return test::compareWithGolden(image, {.golden = golden, .thresholds = kStochasticThresholds}).outcome;
}

TEST(PrismRenderCliStochastic, SamplerFlagOverridesTheSceneAndMatchesItsGolden) {
    // The scene says "bluenoise"; each --sampler gives that sampler's golden (the goldens
    // of tests/scenes), and no other.
    const fs::path dir = testDir();
    for (const char* sampler : {"white", "bluenoise", "sorted"}) {
        const fs::path out = dir / (std::string(sampler) + ".png");
        const auto r =
            runPrismRender({"--scene", kSoftShadows, "--sampler", sampler, "--spp", "1", "--out", out.string()}, dir);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.out.find(std::string(sampler) + ", 1 spp, frame 0"), std::string::npos) << r.out;
        const image::Image8 image = image::readPng(out);
        EXPECT_EQ(image.width, 128);
        EXPECT_EQ(image.height, 128);
        for (const char* other : {"white", "bluenoise", "sorted"})
            EXPECT_EQ(againstSceneGolden(image, other),
                      std::string(sampler) == other ? test::GoldenOutcome::Matches : test::GoldenOutcome::Differs)
                << "--sampler " << sampler << " against the " << other << " golden";
    }
}

TEST(PrismRenderCliStochastic, FrameSppAndFramesChangeTheImage) {
    const fs::path dir = testDir();
    for (const std::vector<std::string>& flags :
         {std::vector<std::string>{"--frame", "1"}, {"--frame", "1000000"}, {"--spp", "4"}, {"--frames", "4"}}) {
        const fs::path out = dir / "out.png";
        fs::remove(out);
        std::vector<std::string> args{"--scene", kSoftShadows, "--out", out.string()};
        args.insert(args.end(), flags.begin(), flags.end());
        const auto r = runPrismRender(args, dir);
        ASSERT_EQ(r.exitCode, 0) << flags[0] << ": " << r.err;
        EXPECT_EQ(againstSceneGolden(image::readPng(out), "bluenoise"), test::GoldenOutcome::Differs)
            << flags[0] << " " << flags[1] << " was ignored";
    }
}

TEST(PrismRenderCliStochastic, FramesIsTheMeanAndFlagsOverrideTheScenesFrames) {
    // A copy of the scene that accumulates 4 frames of the sorted sampler: --frames 4 on
    // the example gives the same image, and --frame 0 on the copy gives frame 0.
    const fs::path dir = testDir();
    std::string text = readText(kSoftShadows);
    const std::string from = "\"sampler\": \"bluenoise\",", to = "\"sampler\": \"sorted\", \"frames\": 4,";
    const std::string frameKey = "\"frame\": 0,";
    ASSERT_NE(text.find(from), std::string::npos);
    ASSERT_NE(text.find(frameKey), std::string::npos);
    text.replace(text.find(from), from.size(), to);
    text.erase(text.find(frameKey), frameKey.size());
    const fs::path scene = writeFile(dir / "four_frames.json", text);
    const auto a = runPrismRender({"--scene", scene.string(), "--out", (dir / "a.png").string()}, dir);
    ASSERT_EQ(a.exitCode, 0) << a.err;
    EXPECT_NE(a.out.find("mean of frames 0..3"), std::string::npos) << a.out;
    const auto b = runPrismRender(
        {"--scene", kSoftShadows, "--sampler", "sorted", "--frames", "4", "--out", (dir / "b.png").string()}, dir);
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_EQ(image::readPng(dir / "a.png"), image::readPng(dir / "b.png"));
    const auto c = runPrismRender({"--scene", scene.string(), "--frame", "0", "--out", (dir / "c.png").string()}, dir);
    ASSERT_EQ(c.exitCode, 0) << c.err;
    EXPECT_EQ(againstSceneGolden(image::readPng(dir / "c.png"), "sorted"), test::GoldenOutcome::Matches);
}

struct StochasticUsage {
    std::vector<std::string> args;  // after --out
    std::string expected;           // in stderr
    std::string testName;
    bool scene = true;  // with --scene soft_shadows.json (else one_light.json)
};

class PrismRenderCliStochasticUsage : public ::testing::TestWithParam<StochasticUsage> {};

TEST_P(PrismRenderCliStochasticUsage, ExitsWithBadInputWritesNothing) {
    const StochasticUsage& p = GetParam();
    const fs::path dir = testDir();
    std::vector<std::string> args{"--scene", p.scene ? kSoftShadows : std::string(PRISM_SCENES_DIR) + "/one_light.json",
                                  "--out", (dir / "out.png").string()};
    args.insert(args.end(), p.args.begin(), p.args.end());
    const auto r = runPrismRender(args, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find(p.expected), std::string::npos) << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, PrismRenderCliStochasticUsage,
    ::testing::Values(StochasticUsage{{"--spp", "2"}, "--spp", "SppWithoutStochastic", false},
                      StochasticUsage{{"--sampler", "white"}, "--sampler", "SamplerWithoutStochastic", false},
                      StochasticUsage{{"--frame", "3"}, "--frame", "FrameWithoutStochastic", false},
                      StochasticUsage{{"--frames", "3"}, "--frames", "FramesWithoutStochastic", false},
                      StochasticUsage{{"--sampler", "pink"}, "--sampler pink", "UnknownSampler"},
                      StochasticUsage{{"--spp", "0"}, "--spp", "ZeroSpp"},
                      StochasticUsage{{"--frames", "0"}, "--frames", "ZeroFrames"},
                      StochasticUsage{{"--frame", "-1"}, "--frame", "NegativeFrame"},
                      StochasticUsage{{"--frame", "1", "--frames", "2"}, "excludes", "FrameAndFrames"},
                      StochasticUsage{{"--sampler", "sorted", "--frame", "200000"}, "sorted", "SortedFrameTooFar"}),
    [](const ::testing::TestParamInfo<StochasticUsage>& info) { return info.param.testName; });

TEST(PrismRenderCliStochastic, FlagsWithShaderAreAUsageError) {
    const fs::path dir = testDir();
    const auto r = runPrismRender(
        {"--shader", "phong", "--size", "32x32", "--sampler", "white", "--out", (dir / "out.png").string()}, dir);
    EXPECT_EQ(r.exitCode, kExitBadInput) << r.err;
    EXPECT_NE(r.err.find("--sampler"), std::string::npos) << r.err;
    EXPECT_TRUE(imagesIn(dir).empty());
}

// --size with --scene overrides the scene's "image" size, for GL and CPU (stochastic)
// scenes alike: the flag is never silently ignored (issue 15).
TEST(PrismRenderCliSceneFlags, SizeOverridesTheScenesImageSize) {
    const fs::path dir = testDir();
    for (const std::string scene : {"one_light", "soft_shadows"}) {
        const fs::path out = dir / (scene + ".png");
        const auto r = runPrismRender({"--scene", std::string(PRISM_SCENES_DIR) + "/" + scene + ".json", "--size",
                                       "80x48", "--out", out.string()},
                                      dir);
        ASSERT_EQ(r.exitCode, 0) << scene << ": " << r.err;
        const image::Image8 image = image::readPng(out);
        EXPECT_EQ(image.width, 80) << scene;
        EXPECT_EQ(image.height, 48) << scene;
    }
}

// Every flag that describes a --shader render is refused with --scene, as is --backend
// for a scene drawn on the CPU, and a malformed --size.
TEST(PrismRenderCliSceneFlags, FlagsTheSceneWouldIgnoreAreUsageErrors) {
    const struct {
        std::vector<std::string> args;
        std::string scene, expected;
    } cases[] = {
        {{"--mesh", "torus"}, "one_light", "--mesh describes a --shader render"},
        {{"--subdiv", "2"}, "one_light", "--subdiv describes a --shader render"},
        {{"--variant", "BLINN=1"}, "one_light", "--variant describes a --shader render"},
        {{"--shininess", "8"}, "one_light", "--shininess describes a --shader render"},
        {{"--specular", "0.2"}, "one_light", "--specular describes a --shader render"},
        {{"--color", "1,0,0"}, "one_light", "--color describes a --shader render"},
        {{"--light-dir", "0,-1,0"}, "one_light", "--light-dir describes a --shader render"},
        {{"--scale", "2,2,2"}, "one_light", "--scale describes a --shader render"},
        {{"--backend", "egl"}, "soft_shadows", "is drawn on the CPU"},
        {{"--size", "80"}, "one_light", "--size 80: expected WxH"},
    };
    for (const auto& c : cases) {
        const fs::path dir = testDir();
        std::vector<std::string> args{"--scene", std::string(PRISM_SCENES_DIR) + "/" + c.scene + ".json", "--out",
                                      (dir / "out.png").string()};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const auto r = runPrismRender(args, dir);
        EXPECT_EQ(r.exitCode, kExitBadInput) << c.args.front() << ": " << r.err;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
        EXPECT_TRUE(imagesIn(dir).empty()) << c.args.front();
    }
}

// --subdiv for a mesh without subdivision levels would be ignored: a usage error instead.
TEST(PrismRenderCli, SubdivForAMeshWithoutLevelsIsAUsageError) {
    for (const std::string mesh : {"cube", "trefoil"}) {
        const fs::path dir = testDir();
        const auto r = runPrismRender({"--shader", "phong", "--mesh", mesh, "--subdiv", "2", "--size", "32x32", "--out",
                                       (dir / "out.png").string()},
                                      dir);
        EXPECT_EQ(r.exitCode, kExitBadInput) << mesh << ": " << r.err;
        EXPECT_NE(r.err.find("--subdiv: mesh " + mesh + " has no subdivision levels"), std::string::npos) << r.err;
        EXPECT_TRUE(imagesIn(dir).empty());
    }
}

}  // namespace
}  // namespace prism::rendering_test
