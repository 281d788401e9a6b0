// The one golden-image check of the tests (prism/test/golden.hpp) on constructed images in a
// scratch folder: a missing golden never passes, the update switch writes and is "skipped"
// (and "0" means off), a difference beyond the thresholds writes actual and diff images under
// PRISM_GOLDEN_OUT, and maxPixelDiff bounds any single pixel.
#include <gtest/gtest.h>

#include <cstdlib>
#include <unistd.h>

#include <filesystem>

#include "prism/image/png_io.hpp"
#include "prism/test/golden.hpp"

namespace {

namespace fs = std::filesystem;
using prism::image::Image8;
using prism::test::GoldenOutcome;

class GoldenCheck : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("prism-golden-check-" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        ::unsetenv("PRISM_UPDATE_GOLDENS");
        ::unsetenv("PRISM_SAVE_ACTUAL");
        ::setenv("PRISM_GOLDEN_OUT", (dir_ / "out").c_str(), 1);
    }
    void TearDown() override {
        ::unsetenv("PRISM_UPDATE_GOLDENS");
        ::unsetenv("PRISM_GOLDEN_OUT");
        fs::remove_all(dir_);
    }
    prism::test::GoldenCheck check(prism::image::Thresholds t = {.maxChannelDiff = 3, .maxShareOver = 0.0}) const {
        return {.golden = dir_ / "golden" / "case.png", .outName = "suite/case", .thresholds = t, .outDir = dir_};
    }
    fs::path dir_;
};

TEST_F(GoldenCheck, AMissingGoldenFailsAndSaysHowToCreateIt) {
    const auto verdict = prism::test::checkGolden(Image8(4, 4, {1, 2, 3, 255}), check());
    EXPECT_EQ(verdict.outcome, GoldenOutcome::Missing);
    EXPECT_NE(verdict.message.find("create it with PRISM_UPDATE_GOLDENS=1"), std::string::npos) << verdict.message;
    EXPECT_FALSE(fs::exists(check().golden));
}

TEST_F(GoldenCheck, UpdateModeWritesTheGoldenAndZeroMeansOff) {
    const Image8 image(4, 4, {10, 20, 30, 255});
    ::setenv("PRISM_UPDATE_GOLDENS", "0", 1);  // off: the golden is still missing
    EXPECT_EQ(prism::test::checkGolden(image, check()).outcome, GoldenOutcome::Missing);
    ::setenv("PRISM_UPDATE_GOLDENS", "1", 1);
    EXPECT_EQ(prism::test::checkGolden(image, check()).outcome, GoldenOutcome::Updated);
    ASSERT_TRUE(fs::exists(check().golden));
    ::unsetenv("PRISM_UPDATE_GOLDENS");
    EXPECT_EQ(prism::test::checkGolden(image, check()).outcome, GoldenOutcome::Matches);
}

TEST_F(GoldenCheck, ADifferenceBeyondTheThresholdsFailsAndWritesActualAndDiff) {
    Image8 image(4, 4, {100, 100, 100, 255});
    prism::image::writePng((fs::create_directories(dir_ / "golden"), check().golden).string(), image);
    image.set(1, 1, {100, 103, 100, 255});  // 3: within maxChannelDiff
    EXPECT_EQ(prism::test::checkGolden(image, check()).outcome, GoldenOutcome::Matches);
    EXPECT_FALSE(fs::exists(dir_ / "out" / "suite" / "case.actual.png"));
    image.set(2, 2, {100, 104, 100, 255});  // 4: one pixel over, none allowed
    const auto verdict = prism::test::checkGolden(image, check());
    EXPECT_EQ(verdict.outcome, GoldenOutcome::Differs) << verdict.message;
    EXPECT_TRUE(fs::exists(dir_ / "out" / "suite" / "case.actual.png"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / "suite" / "case.diff.png"));
}

TEST_F(GoldenCheck, MaxPixelDiffBoundsEveryPixel) {
    Image8 image(10, 10, {100, 100, 100, 255});
    prism::image::writePng((fs::create_directories(dir_ / "golden"), check().golden).string(), image);
    image.set(5, 5, {100, 160, 100, 255});  // one pixel of a hundred, far off
    const prism::image::Thresholds share{.maxChannelDiff = 0, .maxShareOver = 0.05, .maxMean = 1.0};
    EXPECT_EQ(prism::test::compareWithGolden(image, check(share)).outcome, GoldenOutcome::Matches);
    prism::image::Thresholds bounded = share;
    bounded.maxPixelDiff = 1;
    const auto verdict = prism::test::compareWithGolden(image, check(bounded));
    EXPECT_EQ(verdict.outcome, GoldenOutcome::Differs);
    EXPECT_NE(verdict.message.find("no pixel may differ by more than 1"), std::string::npos) << verdict.message;
}

}  // namespace
