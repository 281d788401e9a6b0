// Colour pipeline checks against published CIE numbers: the ybar integral, the D65 white point
// and white under D65 -> sRGB (1, 1, 1), for every supported wavelength step.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "prism/diffraction/colour.hpp"

using namespace prism::diffraction;

TEST(DiffractionColour, YbarIntegralAt5nmIs106857) {
    double sum = 0.0;
    for (int lambda = 380; lambda <= 780; lambda += 5) sum += colourMatching(lambda).y * 5.0;
    std::printf("sum ybar * 5 nm over 380-780 nm = %.4f\n", sum);
    EXPECT_NEAR(sum, 106.857, 0.01);
}

TEST(DiffractionColour, CmfPeaksAtKnownWavelengths) {
    EXPECT_DOUBLE_EQ(colourMatching(555).y, 1.0);  // ybar = 1 at 555 nm (CIE 1931)
    EXPECT_NEAR(colourMatching(600).x, 1.0622, 1e-9);
    EXPECT_NEAR(colourMatching(557.5).y, 0.5 * (1.0 + 0.995), 1e-12);  // linear between samples
    EXPECT_EQ(colourMatching(200).x, 0.0);
}

TEST(DiffractionColour, D65WhitePointForEveryStep) {
    for (int step : {1, 2, 5, 10, 20}) {
        Xyz white;
        for (const SpectralWeight& s : spectralWeights(step)) white = white + s.xyz;
        const double tol = 5e-4;
        std::printf("D65 white at %2d nm: XYZ = (%.5f, %.5f, %.5f)\n", step, white.x, white.y, white.z);
        EXPECT_NEAR(white.x, 0.9505, tol) << step << " nm";
        EXPECT_NEAR(white.y, 1.0, 1e-12) << step << " nm";
        EXPECT_NEAR(white.z, 1.0890, tol) << step << " nm";
    }
}

TEST(DiffractionColour, WhiteUnderD65IsSrgbWhite) {
    for (int step : {1, 2, 5, 10, 20}) {
        Xyz white;
        for (const SpectralWeight& s : spectralWeights(step)) white = white + s.xyz;
        const LinearRgb rgb = xyzToLinearSrgb(white);
        const double tol = 1e-3;
        std::printf("white under D65 at %2d nm: linear sRGB = (%.5f, %.5f, %.5f)\n", step, rgb.r, rgb.g, rgb.b);
        EXPECT_NEAR(rgb.r, 1.0, tol) << step << " nm";
        EXPECT_NEAR(rgb.g, 1.0, tol) << step << " nm";
        EXPECT_NEAR(rgb.b, 1.0, tol) << step << " nm";
    }
}

TEST(DiffractionColour, GridCoversTheVisibleRange) {
    const std::vector<SpectralWeight> grid = spectralWeights(20);
    ASSERT_EQ(grid.size(), 21u);
    EXPECT_EQ(grid.front().wavelengthNm, 380.0);
    EXPECT_EQ(grid.back().wavelengthNm, 780.0);
    EXPECT_EQ(spectralWeights(1).size(), 401u);
}

TEST(DiffractionColour, UnsupportedStepIsAClearError) {
    try {
        spectralWeights(3);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("1, 2, 5, 10 or 20"), std::string::npos) << e.what();
    }
}

TEST(DiffractionColour, TablesRecordTheirSource) {
    EXPECT_NE(cmfSource().find("CIE1931-2deg-XYZ.cmf"), std::string::npos);
    EXPECT_NE(cmfSource().find("sha256"), std::string::npos);
    EXPECT_NE(d65Source().find("CIE-D65.sp"), std::string::npos);
}

TEST(DiffractionColour, SrgbEncodeClampsAndMatchesTheStandard) {
    EXPECT_EQ(srgbEncode(-1.0), 0.0);
    EXPECT_NEAR(srgbEncode(2.0), 1.0, 1e-12);
    EXPECT_NEAR(srgbEncode(0.18), 0.4614, 1e-4);  // 18 % grey -> 118/255
}
