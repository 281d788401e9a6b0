// Grey PNG files: 8- and 16-bit round trips, atomic writes that skip unchanged content,
// and errors that name the file.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "prism/bluenoise/gray_png.hpp"

namespace bn = prism::bluenoise;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("prism_bluenoise_png_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}
}  // namespace

TEST(GrayPng, RoundTrips8And16Bits) {
    for (int bits : {8, 16}) {
        bn::GrayImage image{5, 3, bits, {}};
        for (int i = 0; i < 15; ++i) image.values.push_back(static_cast<std::uint16_t>((i * 4099) & ((1 << bits) - 1)));
        const fs::path path = scratch("round" + std::to_string(bits) + "/m.png");  // parent created
        bn::writeGrayPng(path, image);
        const bn::GrayImage back = bn::readGrayPng(path);
        EXPECT_EQ(back.width, 5);
        EXPECT_EQ(back.height, 3);
        EXPECT_EQ(back.bits, bits);
        EXPECT_EQ(back.values, image.values);
        for (const auto& entry : fs::directory_iterator(path.parent_path()))
            EXPECT_EQ(entry.path().filename(), "m.png") << "temporary file left behind";
    }
}

TEST(GrayPng, UnchangedContentIsNotRewritten) {
    const fs::path path = scratch("same.png");
    bn::GrayImage image{2, 2, 8, {1, 2, 3, 4}};
    bn::writeGrayPng(path, image);
    const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
    fs::last_write_time(path, old);
    bn::writeGrayPng(path, image);
    EXPECT_EQ(fs::last_write_time(path), old);
    image.values[0] = 9;
    bn::writeGrayPng(path, image);
    EXPECT_NE(fs::last_write_time(path), old);
}

TEST(GrayPng, ErrorsNameTheFile) {
    const fs::path bogus = scratch("not-a-png.png");
    std::ofstream(bogus) << "hello";
    try {
        bn::readGrayPng(bogus);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(bogus.string()), std::string::npos) << e.what();
    }
    EXPECT_THROW(bn::readGrayPng(scratch("missing.png")), std::runtime_error);
    EXPECT_THROW(bn::writeGrayPng(scratch("empty.png"), bn::GrayImage{}), std::runtime_error);
}
