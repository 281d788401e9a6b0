// Height and permeability maps: 8- and 16-bit PNGs through the water system's own
// libpng path, procedural terrain and soil, and clear errors naming the file.
#include <gtest/gtest.h>

#include <png.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "prism/image/png_io.hpp"
#include "prism/water/height_field.hpp"
#include "prism/water/rain_rates.hpp"
#include "water_test_support.hpp"

namespace prism::water {
namespace {

namespace fs = std::filesystem;

// A PNG of any bit depth and colour type, written with libpng directly (the library
// only writes 8/16-bit grey), to check what the loader rejects.
void writeRawPng(const fs::path& path, int width, int height, int bitDepth, int colorType) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bitDepth, colorType,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_color palette[2] = {{0, 0, 0}, {255, 255, 255}};
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, 2);
    png_write_info(png, info);
    std::vector<unsigned char> row(static_cast<std::size_t>(width) * 8, 0x01);  // a valid palette index too
    for (int y = 0; y < height; ++y) png_write_row(png, row.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

std::string loadError(const fs::path& path) {
    try {
        loadHeightMap(path);
    } catch (const HeightMapError& e) {
        return e.what();
    }
    return "";
}

TEST(HeightMaps, SixteenBitSamplesRoundTripExactly) {
    const fs::path dir = test::scratchDir("height16");
    GreyImage img;
    img.width = 5;
    img.height = 3;
    img.bitDepth = 16;
    for (int i = 0; i < 15; ++i) img.values.push_back(static_cast<std::uint16_t>(i * 4369 + 1));  // spans 1..61167
    writeGreyPng(dir / "h16.png", img);
    const GreyImage back = readGreyPng(dir / "h16.png");
    EXPECT_EQ(back.bitDepth, 16);
    EXPECT_EQ(back.values, img.values) << "16-bit samples must not be reduced to 8 bits";
    const HeightField f =
        loadHeightMap(dir / "h16.png", {.cellSize = 0.5f, .heightScale = 65.535f, .baseHeight = 1.0f});
    EXPECT_EQ(f.width, 5);
    EXPECT_EQ(f.height, 3);
    EXPECT_FLOAT_EQ(f.cellSize, 0.5f);
    EXPECT_EQ(f.origin, 1.0) << "the base height is the local origin";
    EXPECT_NEAR(f.at(0, 0), 0.001f, 1e-9f);
    EXPECT_NEAR(f.at(4, 2), 61.167f, 1e-5f);
}

TEST(HeightMaps, EightBitAndRgbUseTheFirstChannel) {
    const fs::path dir = test::scratchDir("height8");
    GreyImage img{4, 4, 8, std::vector<std::uint16_t>(16, 255)};
    img.values[5] = 0;
    writeGreyPng(dir / "h8.png", img);
    const HeightField f = loadHeightMap(dir / "h8.png", {.heightScale = 10.0f});
    EXPECT_FLOAT_EQ(f.at(0, 0), 10.0f);
    EXPECT_FLOAT_EQ(f.at(1, 1), 0.0f);
    image::Image8 rgba(3, 2, {200, 10, 20, 255});
    image::writePng(dir / "rgba.png", rgba);
    const HeightField g = loadHeightMap(dir / "rgba.png", {.heightScale = 255.0f});
    EXPECT_FLOAT_EQ(g.at(2, 1), 200.0f) << "the red channel";
}

TEST(HeightMaps, NonSquareMapsAreSupported) {
    const fs::path dir = test::scratchDir("nonsquare");
    GreyImage img{7, 3, 8, std::vector<std::uint16_t>(21, 100)};
    writeGreyPng(dir / "wide.png", img);
    const HeightField f = loadHeightMap(dir / "wide.png");
    EXPECT_EQ(f.width, 7);
    EXPECT_EQ(f.height, 3);
    CpuWaterSimulation sim(f, {}, {});
    sim.setRainRate(1e-4);
    sim.advance(1.0);
    EXPECT_NEAR(sim.ledger().relativeError(), 0.0, 1e-9);
}

TEST(HeightMaps, MissingFileIsNamed) {
    const std::string msg = loadError("/nonexistent/dir/terrain-missing.png");
    EXPECT_NE(msg.find("terrain-missing.png"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

TEST(HeightMaps, WrongBitDepthIsNamed) {
    const fs::path dir = test::scratchDir("bitdepth");
    writeRawPng(dir / "four-bit.png", 8, 8, 4, PNG_COLOR_TYPE_GRAY);
    std::string msg = loadError(dir / "four-bit.png");
    EXPECT_NE(msg.find("four-bit.png"), std::string::npos) << msg;
    EXPECT_NE(msg.find("4-bit"), std::string::npos) << msg;
    EXPECT_NE(msg.find("8 or 16 bits"), std::string::npos) << msg;
    writeRawPng(dir / "one-bit.png", 8, 8, 1, PNG_COLOR_TYPE_GRAY);
    msg = loadError(dir / "one-bit.png");
    EXPECT_NE(msg.find("one-bit.png: 1-bit PNG"), std::string::npos) << msg;
    writeRawPng(dir / "palette.png", 8, 8, 8, PNG_COLOR_TYPE_PALETTE);
    msg = loadError(dir / "palette.png");
    EXPECT_NE(msg.find("palette.png: palette PNG"), std::string::npos) << msg;
}

TEST(HeightMaps, NotAPngAndTruncatedFilesAreNamed) {
    const fs::path dir = test::scratchDir("corrupt");
    std::ofstream(dir / "text.png") << "this is not a png";
    std::string msg = loadError(dir / "text.png");
    EXPECT_NE(msg.find("text.png: not a PNG file"), std::string::npos) << msg;
    GreyImage img{16, 16, 8, std::vector<std::uint16_t>(256, 7)};
    writeGreyPng(dir / "whole.png", img);
    const auto size = fs::file_size(dir / "whole.png");
    fs::copy_file(dir / "whole.png", dir / "cut.png");
    fs::resize_file(dir / "cut.png", size / 2);
    msg = loadError(dir / "cut.png");
    EXPECT_NE(msg.find("cut.png"), std::string::npos) << msg;
}

TEST(PermeabilityMaps, ScaleAndSizeCheck) {
    const fs::path dir = test::scratchDir("permeability");
    GreyImage img{4, 2, 8, {0, 51, 102, 153, 204, 255, 255, 0}};
    writeGreyPng(dir / "soil.png", img);
    const double maxRate = mmPerHourToMetresPerSecond(36.0);
    const std::vector<float> k = loadPermeabilityMap(dir / "soil.png", 4, 2, maxRate);
    ASSERT_EQ(k.size(), 8u);
    EXPECT_FLOAT_EQ(k[0], 0.0f);
    EXPECT_FLOAT_EQ(k[5], static_cast<float>(maxRate));
    EXPECT_NEAR(k[1], maxRate * 0.2, 1e-12);
    try {
        loadPermeabilityMap(dir / "soil.png", 8, 8, maxRate);
        FAIL() << "no exception";
    } catch (const HeightMapError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("soil.png"), std::string::npos) << msg;
        EXPECT_NE(msg.find("4x2"), std::string::npos) << msg;
        EXPECT_NE(msg.find("8x8"), std::string::npos) << msg;
    }
}

TEST(ProceduralMaps, DeterministicTerrainWithReliefAndSoil) {
    const HeightField a = proceduralTerrain({.width = 64, .height = 48, .cellSize = 0.5f, .seed = 3});
    const HeightField b = proceduralTerrain({.width = 64, .height = 48, .cellSize = 0.5f, .seed = 3});
    const HeightField c = proceduralTerrain({.width = 64, .height = 48, .cellSize = 0.5f, .seed = 4});
    EXPECT_EQ(a.heights, b.heights);
    EXPECT_NE(a.heights, c.heights);
    const auto [lo, hi] = std::minmax_element(a.heights.begin(), a.heights.end());
    EXPECT_GT(*hi - *lo, 1.0f) << "hills";
    const std::vector<float> k = proceduralPermeability(a);
    const auto [kmin, kmax] = std::minmax_element(k.begin(), k.end());
    EXPECT_GE(*kmin, 0.0f);
    EXPECT_GT(*kmax, 5.0f * *kmin) << "patches of soil and compacted ground";
}

}  // namespace
}  // namespace prism::water
