// CIEDE2000 against Sharma, Wu & Dalal (2005), Table 1, and CIELAB of sRGB white and black.
#include <gtest/gtest.h>

#include "prism/diffraction/colour_difference.hpp"

using namespace prism::diffraction;

TEST(DiffractionColourDifference, SharmaTestPairs) {
    const struct {
        Lab a, b;
        double de;
    } pairs[] = {
        {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},             // pair 1
        {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},                         // pair 7
        {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},                      // pair 17
        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},  // pair 25
    };
    for (const auto& p : pairs) {
        EXPECT_NEAR(ciede2000(p.a, p.b), p.de, 1e-4);
        EXPECT_NEAR(ciede2000(p.b, p.a), p.de, 1e-4);  // symmetric
    }
    EXPECT_EQ(ciede2000({40, 10, 10}, {40, 10, 10}), 0.0);
}

TEST(DiffractionColourDifference, SrgbWhiteAndBlack) {
    const Lab white = linearSrgbToLab({1, 1, 1});
    EXPECT_NEAR(white.l, 100.0, 1e-2);
    EXPECT_NEAR(white.a, 0.0, 0.05);
    EXPECT_NEAR(white.b, 0.0, 0.05);
    const Lab black = linearSrgbToLab({0, 0, 0});
    EXPECT_NEAR(black.l, 0.0, 1e-9);
}
