// Loads a user's 8- or 16-bit PNG as a height field with libpng (see height_field.hpp).
#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "prism/diffraction/height_field.hpp"

namespace prism::diffraction {
namespace {

struct File {
    std::FILE* f = nullptr;
    ~File() {
        if (f) std::fclose(f);
    }
};

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw std::runtime_error(path + ": error: " + what);
}

}  // namespace

HeightField loadHeightFieldPng(const std::string& path, double nmPerPixel, double heightScaleNm) {
    if (!(std::isfinite(nmPerPixel) && nmPerPixel > 0.0)) fail(path, "nm per pixel must be > 0");
    if (!(std::isfinite(heightScaleNm) && heightScaleNm >= 0.0)) fail(path, "height scale must be >= 0 nm");
    File file;
    file.f = std::fopen(path.c_str(), "rb");
    if (!file.f) fail(path, "cannot open the height-field PNG");
    unsigned char signature[8] = {};
    if (std::fread(signature, 1, 8, file.f) != 8 || png_sig_cmp(signature, 0, 8) != 0) {
        fail(path, "not a PNG file (bad signature)");
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        fail(path, "out of memory creating the PNG reader");
    }
    if (setjmp(png_jmpbuf(png)) != 0) {
        png_destroy_read_struct(&png, &info, nullptr);
        fail(path, "corrupt or truncated PNG data");
    }
    png_init_io(png, file.f);
    png_set_sig_bytes(png, 8);
    png_read_png(png, info, PNG_TRANSFORM_EXPAND | PNG_TRANSFORM_STRIP_ALPHA, nullptr);
    const int width = static_cast<int>(png_get_image_width(png, info));
    const int height = static_cast<int>(png_get_image_height(png, info));
    const int depth = png_get_bit_depth(png, info);
    const int channels = png_get_channels(png, info);
    png_bytepp rows = png_get_rows(png, info);
    std::string problem;
    if (depth != 8 && depth != 16)
        problem = "bit depth " + std::to_string(depth) + " is not supported (use 8 or 16 bits)";
    if (width < 1 || height < 1 || width > 8192 || height > 8192)
        problem = "image size must be 1..8192 pixels per side";
    HeightField field;
    if (problem.empty()) {
        field.width = width;
        field.height = height;
        field.pixelNm = nmPerPixel;
        field.heightsNm.resize(static_cast<std::size_t>(width) * height);
        const double maxValue = depth == 16 ? 65535.0 : 255.0;
        const int bytes = depth / 8;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const png_bytep p = rows[y] + static_cast<std::size_t>(x) * channels * bytes;
                const double value = bytes == 2 ? (p[0] << 8 | p[1]) : p[0];  // PNG is big-endian
                field.heightsNm[static_cast<std::size_t>(y) * width + x] = value / maxValue * heightScaleNm;
            }
        }
    }
    png_destroy_read_struct(&png, &info, nullptr);
    if (!problem.empty()) fail(path, problem);
    return field;
}

}  // namespace prism::diffraction
