// Golden-image comparison statistics on constructed images (no GL).
#include <gtest/gtest.h>

#include "prism/image/image_compare.hpp"

namespace {

using prism::image::Image8;
using prism::image::Thresholds;

TEST(ImageCompare, IdenticalImagesHaveZeroStats) {
    const Image8 a(8, 8, {10, 20, 30, 255});
    const auto cmp = prism::image::compareImages(a, a);
    EXPECT_TRUE(cmp.sizeMatches);
    EXPECT_EQ(cmp.maxChannelDiff, 0);
    EXPECT_EQ(cmp.pixelsOver, 0u);
    EXPECT_DOUBLE_EQ(cmp.meanAbsError, 0.0);
    EXPECT_TRUE(prism::image::passes(cmp, Thresholds{0, 0.0, 0.0}));
    EXPECT_EQ(cmp.diff.at(4, 4), (prism::image::Rgba8{0, 0, 0, 255}));
}

TEST(ImageCompare, OnePixelChangedByTen) {
    const Image8 expected(10, 10, {100, 100, 100, 255});
    Image8 actual = expected;
    actual.set(3, 7, {100, 110, 100, 255});  // green +10
    const auto cmp = prism::image::compareImages(actual, expected, 3);
    EXPECT_EQ(cmp.maxChannelDiff, 10);
    EXPECT_EQ(cmp.pixelsOver, 1u);
    EXPECT_DOUBLE_EQ(cmp.shareOver, 1.0 / 100.0);
    EXPECT_DOUBLE_EQ(cmp.meanAbsError, 10.0 / 400.0);  // 10 over 100 pixels x 4 channels
    EXPECT_EQ(cmp.maxDiffHistogram[10], 1u);
    EXPECT_EQ(cmp.maxDiffHistogram[0], 99u);
    EXPECT_EQ(cmp.diff.at(3, 7), (prism::image::Rgba8{0, 80, 0, 255}));  // amplified x8
    EXPECT_EQ(cmp.diff.at(0, 0), (prism::image::Rgba8{0, 0, 0, 255}));

    EXPECT_TRUE(prism::image::passes(cmp, Thresholds{3, 0.01, 0.5}));    // 1% allowed
    EXPECT_FALSE(prism::image::passes(cmp, Thresholds{3, 0.005, 0.5}));  // only 0.5% allowed
    EXPECT_TRUE(prism::image::passes(cmp, Thresholds{10, 0.0, 0.5}));    // 10 is not above 10
    EXPECT_FALSE(prism::image::passes(cmp, Thresholds{9, 0.0, 0.5}));
    EXPECT_FALSE(prism::image::passes(cmp, Thresholds{255, 1.0, 0.02}));  // mean 0.025 > 0.02
    EXPECT_NE(prism::image::describe(cmp, Thresholds{3, 0.005, 0.5}).find("FAIL"), std::string::npos);
}

TEST(ImageCompare, AlphaOnlyDifferenceShowsInDiffImage) {
    const Image8 expected(2, 2, {0, 0, 0, 255});
    Image8 actual = expected;
    actual.set(1, 1, {0, 0, 0, 0});
    const auto cmp = prism::image::compareImages(actual, expected);
    EXPECT_EQ(cmp.maxChannelDiff, 255);
    EXPECT_EQ(cmp.diff.at(1, 1), (prism::image::Rgba8{255, 255, 255, 255}));  // clamped
}

TEST(ImageCompare, SizeMismatchIsReportedAndFails) {
    const auto cmp = prism::image::compareImages(Image8(64, 32), Image8(64, 64));
    EXPECT_FALSE(cmp.sizeMatches);
    EXPECT_EQ(cmp.sizeMessage, "size differs: actual 64x32, expected 64x64");
    EXPECT_FALSE(prism::image::passes(cmp, Thresholds{255, 1.0, 255.0}));
    EXPECT_EQ(prism::image::describe(cmp, Thresholds{}), cmp.sizeMessage);
}

TEST(ImageCompare, EmptyImagesGiveNoNan) {
    const auto cmp = prism::image::compareImages(Image8(0, 0), Image8(0, 0));
    EXPECT_TRUE(cmp.sizeMatches);
    EXPECT_EQ(cmp.shareOver, 0.0);
    EXPECT_EQ(cmp.meanAbsError, 0.0);
    EXPECT_TRUE(prism::image::passes(cmp, Thresholds{}));
}

}  // namespace
