// CPU image helpers: access checks, non-finite counts and conversions (no GL).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "prism/image/image.hpp"

namespace {

TEST(Image, FillAccessAndBounds) {
    prism::image::Image8 img(3, 2, {1, 2, 3, 4});
    EXPECT_EQ(img.data.size(), 24u);
    EXPECT_EQ(img.at(2, 1), (prism::image::Rgba8{1, 2, 3, 4}));
    img.set(2, 1, {9, 9, 9, 9});
    EXPECT_EQ(img.data[20], 9);
    EXPECT_THROW(img.at(3, 0), std::out_of_range);
    EXPECT_THROW(img.set(0, -1, {}), std::out_of_range);
}

TEST(Image, FlipPutsFirstRowLast) {
    prism::image::Image8 img(2, 3);
    img.set(1, 0, {255, 0, 0, 255});
    const prism::image::Image8 flipped = prism::image::flippedVertically(img);
    EXPECT_EQ(flipped.at(1, 2), (prism::image::Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(flipped.at(1, 0), (prism::image::Rgba8{0, 0, 0, 0}));
}

TEST(Image, CountNonFiniteCountsPixels) {
    prism::image::ImageF img(4, 4, {0.5f, 0.5f, 0.5f, 1.f});
    EXPECT_EQ(prism::image::countNonFinite(img), 0u);
    img.set(0, 0, {std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f, 1.f});
    img.set(3, 3, {0.f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), 1.f});
    EXPECT_EQ(prism::image::countNonFinite(img), 2u);
}

TEST(Image, ToImage8ClampsAndMapsNanToZero) {
    prism::image::ImageF img(1, 1, {std::numeric_limits<float>::quiet_NaN(), 2.0f, -1.0f, 0.5f});
    EXPECT_EQ(prism::image::toImage8(img).at(0, 0), (prism::image::Rgba8{0, 255, 0, 128}));
    const prism::image::ImageF back = prism::image::toImageF(prism::image::Image8(1, 1, {255, 0, 51, 255}));
    EXPECT_FLOAT_EQ(back.at(0, 0)[2], 0.2f);
}

}  // namespace
