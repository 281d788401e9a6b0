// prism-render --scene run as a program on the diffraction example scenes: it exits 0,
// writes the PNG and reports each diffraction draw on the path the scene asks for (the CD
// disc on path c, DIFFRACTION_PATH=2; the grating and the snake on path b, 1).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "prism/test/run_command.hpp"

namespace {

namespace fs = std::filesystem;

void expectDrawnOnPath(const std::string& scene, int path) {
    const fs::path out = fs::path(PRISM_SCENE_CLI_OUT) / (scene + ".png");
    fs::create_directories(out.parent_path());
    fs::remove(out);
    const auto r =
        prism::test::runCommand({PRISM_RENDER_EXECUTABLE, "--scene",
                                 std::string(PRISM_SCENES_DIR) + "/" + scene + ".json", "--out", out.string()});
    EXPECT_EQ(r.exitCode, 0) << r;
    const std::regex draw("draw: diffraction [^\\n]*DIFFRACTION_PATH=" + std::to_string(path));
    EXPECT_TRUE(std::regex_search(r.out, draw) || std::regex_search(r.err, draw)) << r;
    EXPECT_TRUE(fs::is_regular_file(out)) << r;
}

}  // namespace

TEST(SceneCli, render_diffraction_cd) {
    expectDrawnOnPath("diffraction_cd", 2);
}

TEST(SceneCli, render_diffraction_grating) {
    expectDrawnOnPath("diffraction_grating", 1);
}

TEST(SceneCli, render_diffraction_snake) {
    expectDrawnOnPath("diffraction_snake", 1);
}
