// PNG round trip, atomic writes and errors that name the file (no GL).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "prism/image/png_io.hpp"

namespace {

namespace fs = std::filesystem;

class PngTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("prism_png_test_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

prism::image::Image8 pattern(int w, int h) {
    prism::image::Image8 img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.set(x, y,
                    {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 13),
                     static_cast<std::uint8_t>((x ^ y) * 3), static_cast<std::uint8_t>(255 - x - y)});
    return img;
}

TEST_F(PngTest, RoundTripIsExactAndLeavesNoTempFile) {
    const prism::image::Image8 img = pattern(37, 19);  // odd width: no row padding assumptions
    const fs::path file = dir_ / "nested" / "pattern.png";
    prism::image::writePng(file, img);
    EXPECT_EQ(prism::image::readPng(file), img);
    std::size_t entries = 0;
    for (const auto& e : fs::directory_iterator(file.parent_path())) {
        ++entries;
        EXPECT_EQ(e.path().filename(), "pattern.png");
    }
    EXPECT_EQ(entries, 1u);
    // Overwriting replaces the file.
    const prism::image::Image8 other = pattern(5, 5);
    prism::image::writePng(file, other);
    EXPECT_EQ(prism::image::readPng(file), other);
}

TEST_F(PngTest, ReadErrorsNameTheFile) {
    const fs::path missing = dir_ / "missing.png";
    try {
        prism::image::readPng(missing);
        FAIL() << "reading a missing file succeeded";
    } catch (const prism::image::PngError& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    fs::create_directories(dir_);
    const fs::path notPng = dir_ / "text.png";
    std::ofstream(notPng) << "this is not a PNG file";
    try {
        prism::image::readPng(notPng);
        FAIL() << "reading a text file as PNG succeeded";
    } catch (const prism::image::PngError& e) {
        EXPECT_NE(std::string(e.what()).find(notPng.string()), std::string::npos) << e.what();
    }
}

TEST_F(PngTest, WriteErrorsNameTheFile) {
    fs::create_directories(dir_);
    std::ofstream(dir_ / "plainfile") << "x";
    const fs::path impossible = dir_ / "plainfile" / "out.png";  // parent is a file
    try {
        prism::image::writePng(impossible, pattern(2, 2));
        FAIL() << "writing below a plain file succeeded";
    } catch (const prism::image::PngError& e) {
        EXPECT_NE(std::string(e.what()).find(impossible.string()), std::string::npos) << e.what();
    }
    EXPECT_THROW(prism::image::writePng(dir_ / "empty.png", prism::image::Image8{}), prism::image::PngError);
    EXPECT_FALSE(fs::exists(dir_ / "empty.png"));
}

}  // namespace
