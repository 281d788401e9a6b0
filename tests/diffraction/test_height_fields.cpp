// Height fields: the procedural patterns have the spectra they claim, and user PNGs of 8 and 16
// bits load with their nm scales (bad files are clear errors naming the file).
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "prism/diffraction/lookup_tables.hpp"
#include "prism/diffraction/spectrum.hpp"

using namespace prism::diffraction;

namespace {

std::string tmpPath(const std::string& name) {
    std::filesystem::create_directories(PRISM_DIFFRACTION_TEST_TMP);
    return std::string(PRISM_DIFFRACTION_TEST_TMP) + "/" + name;
}

void writeGreyPng(const std::string& path, int w, int h, int depth, const std::vector<int>& values) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, depth, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const int bytes = depth / 8;
    std::vector<unsigned char> row(static_cast<std::size_t>(w) * bytes);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int v = values[static_cast<std::size_t>(y) * w + x];
            if (bytes == 2) {
                row[2 * x] = static_cast<unsigned char>(v >> 8);
                row[2 * x + 1] = static_cast<unsigned char>(v & 0xff);
            } else {
                row[x] = static_cast<unsigned char>(v);
            }
        }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

// The strongest non-DC line of a field's spectrum along x, in cycles per nm.
double dominantFrequencyX(const HeightField& field) {
    HeightField centred = field;
    subtractMean(centred);
    std::vector<std::complex<double>> samples(centred.heightsNm.begin(), centred.heightsNm.end());
    const Spectrum s = fourierSeries(samples, centred.width, centred.height, centred.pixelNm);
    int best = 1;
    for (int j = 1; j < centred.width / 2; ++j) {
        if (std::norm(s.coefficient(j, 0)) > std::norm(s.coefficient(best, 0))) best = j;
    }
    return best / s.periodXNm;
}

}  // namespace

TEST(DiffractionHeightFields, SinusoidAndBlazedShapes) {
    const HeightField s = sinusoidGrating({.periodNm = 2000, .amplitudeNm = 100, .periods = 2, .samplesPerPeriod = 8});
    EXPECT_EQ(s.width, 16);
    EXPECT_EQ(s.height, 1);
    EXPECT_DOUBLE_EQ(s.pixelNm, 250.0);
    EXPECT_NEAR(s.at(2, 0), 100.0, 1e-9);  // quarter period
    const HeightField b = blazedGrating({.periodNm = 2000, .amplitudeNm = 100, .periods = 2, .samplesPerPeriod = 8});
    EXPECT_NEAR(b.at(4, 0), 100.0, 1e-9);
    EXPECT_NEAR(b.at(8, 0), 0.0, 1e-9);  // the saw drops at each period
    EXPECT_NEAR(dominantFrequencyX(s), 1.0 / 2000.0, 1e-12);
}

TEST(DiffractionHeightFields, BadGratingParametersAreErrors) {
    EXPECT_THROW(sinusoidGrating({.periodNm = -2500}), std::invalid_argument);
    EXPECT_THROW(sinusoidGrating({.amplitudeNm = -1}), std::invalid_argument);
    EXPECT_THROW(blazedGrating({.periods = 0}), std::invalid_argument);
}

TEST(DiffractionHeightFields, CdTracksHaveThe1600nmPitch) {
    const HeightField cd = cdTracks({.size = 256, .pixelNm = 100.0});
    // 25.6 um holds 16 tracks of 1600 nm exactly.
    EXPECT_NEAR(1.0 / dominantFrequencyX(cd), 1600.0, 1e-6);
    EXPECT_LT(*std::min_element(cd.heightsNm.begin(), cd.heightsNm.end()), -100.0);  // pits
}

TEST(DiffractionHeightFields, SnakeRidgesAreQuasiPeriodic) {
    const HeightField ridges = snakeRidges({.spacingNm = 1400.0, .size = 256, .pixelNm = 100.0});
    const double period = 1.0 / dominantFrequencyX(ridges);
    EXPECT_NEAR(period, 1400.0, 150.0);  // about the spacing, not exactly (jitter)
    HeightField centred = ridges;
    subtractMean(centred);
    EXPECT_GT(maxAbsHeight(centred), 50.0);
    EXPECT_NE(snakeRidges({.seed = 2}).heightsNm, snakeRidges({.seed = 1}).heightsNm);
}

TEST(DiffractionHeightFields, Png8And16BitLoadWithTheirScales) {
    const std::string p8 = tmpPath("h8.png"), p16 = tmpPath("h16.png");
    writeGreyPng(p8, 3, 2, 8, {0, 255, 51, 0, 0, 0});
    writeGreyPng(p16, 2, 1, 16, {65535, 257});
    const HeightField a = loadHeightFieldPng(p8, 50.0, 200.0);
    EXPECT_EQ(a.width, 3);
    EXPECT_EQ(a.height, 2);
    EXPECT_DOUBLE_EQ(a.pixelNm, 50.0);
    EXPECT_NEAR(a.at(1, 0), 200.0, 1e-12);
    EXPECT_NEAR(a.at(2, 0), 40.0, 1e-12);
    const HeightField b = loadHeightFieldPng(p16, 10.0, 1000.0);
    EXPECT_NEAR(b.at(0, 0), 1000.0, 1e-12);
    EXPECT_NEAR(b.at(1, 0), 1000.0 * 257.0 / 65535.0, 1e-12);  // both bytes count
}

TEST(DiffractionHeightFields, UnreadablePngIsAClearError) {
    const std::string missing = tmpPath("missing.png");
    std::filesystem::remove(missing);
    try {
        loadHeightFieldPng(missing, 10.0, 100.0);
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(missing + ": error:"), std::string::npos) << e.what();
    }
    const std::string text = tmpPath("text.png");
    std::ofstream(text) << "not a png";
    EXPECT_THROW(loadHeightFieldPng(text, 10.0, 100.0), std::runtime_error);
    const std::string truncated = tmpPath("truncated.png");
    writeGreyPng(truncated, 64, 64, 8, std::vector<int>(64 * 64, 7));
    std::filesystem::resize_file(truncated, 60);
    EXPECT_THROW(loadHeightFieldPng(truncated, 10.0, 100.0), std::runtime_error);
    EXPECT_THROW(loadHeightFieldPng(tmpPath("h8.png"), -1.0, 100.0), std::runtime_error);
}

TEST(DiffractionHeightFields, DocsBringYourOwnHeightField) {
    // docs/diffraction.md, "Bring your own height field", with a 32 x 32 ridge PNG.
    std::vector<int> ridges;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) ridges.push_back((x % 8) < 3 ? 255 : 0);
    }
    const std::string path = tmpPath("ridges.png");
    writeGreyPng(path, 32, 32, 8, ridges);
    auto field = prism::diffraction::loadHeightFieldPng(path, /*nm per pixel*/ 100, /*height scale nm*/ 150);
    prism::diffraction::StamBrdf brdf(field, {.tolerance = 1e-4});
    auto tables =
        prism::diffraction::buildIntegratedTables(prism::diffraction::buildSpectralTables(brdf, {.size = 64}));
    EXPECT_EQ(tables.terms, brdf.terms());
    EXPECT_EQ(tables.bytes(), (2u * brdf.terms() + 1u) * 64u * 64u * 3u * sizeof(float));
}
