// Grey 8/16-bit PNG reading and writing with libpng's classic API; atomic file writes.
#include "prism/bluenoise/gray_png.hpp"

#include <png.h>
#include <unistd.h>

#include <csetjmp>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism::bluenoise {
namespace {

struct PngErrorState {
    char message[256] = "libpng failed";
};

void onPngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}
void onPngWarning(png_structp, png_const_charp) {}

void appendBytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + length);
}
void flushNothing(png_structp) {}

std::string failure(const char* verb, const std::filesystem::path& path, const std::string& reason) {
    std::string out = path.string();
    out += ": error: cannot ";
    out += verb;
    out += " PNG: ";
    out += reason;
    return out;
}

// Encodes into `out`; returns false with state.message set on a libpng error.
bool encode(const GrayImage& image, std::vector<unsigned char>& out, PngErrorState& state, std::vector<png_bytep>& rows,
            std::vector<unsigned char>& pixels) {
    const int bytesPerValue = image.bits == 16 ? 2 : 1;
    pixels.resize(image.size() * static_cast<std::size_t>(bytesPerValue));
    for (std::size_t i = 0; i < image.size(); ++i) {
        if (bytesPerValue == 2) {  // PNG stores 16-bit samples big-endian
            pixels[2 * i] = static_cast<unsigned char>(image.values[i] >> 8);
            pixels[2 * i + 1] = static_cast<unsigned char>(image.values[i] & 0xFF);
        } else {
            pixels[i] = static_cast<unsigned char>(image.values[i]);
        }
    }
    rows.resize(static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y)
        rows[static_cast<std::size_t>(y)] =
            pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width * bytesPerValue);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &out, appendBytes, flushNothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), image.bits,
                 PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    {
        std::ifstream existing(path, std::ios::binary);
        if (existing) {
            const std::string old((std::istreambuf_iterator<char>(existing)), std::istreambuf_iterator<char>());
            if (old == bytes) return;
        }
    }
    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec) throw std::runtime_error(path.string() + ": error: cannot create its directory: " + ec.message());
    }
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out.flush()) {
            std::filesystem::remove(temp, ec);
            throw std::runtime_error(path.string() + ": error: cannot write (check that the directory is writable)");
        }
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw std::runtime_error(path.string() + ": error: cannot rename the temporary file: " + ec.message());
    }
}

void writeGrayPng(const std::filesystem::path& path, const GrayImage& image) {
    if (image.bits != 8 && image.bits != 16)
        throw std::runtime_error(failure("write", path, "bits must be 8 or 16, got " + std::to_string(image.bits)));
    if (image.width < 1 || image.height < 1 ||
        image.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
        throw std::runtime_error(failure("write", path, "the image is empty or its size does not match its values"));
    std::vector<unsigned char> bytes;
    std::vector<png_bytep> rows;
    std::vector<unsigned char> pixels;
    PngErrorState state;
    if (!encode(image, bytes, state, rows, pixels)) throw std::runtime_error(failure("write", path, state.message));
    writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

GrayImage readGrayPng(const std::filesystem::path& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) throw std::runtime_error(failure("read", path, "cannot open the file (does it exist?)"));
    PngErrorState state;
    GrayImage image;
    std::vector<unsigned char> pixels;
    std::vector<png_bytep> rows;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(file);
        throw std::runtime_error(failure("read", path, "out of memory"));
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(file);
        throw std::runtime_error(failure("read", path, std::string(state.message) + " (is it a PNG file?)"));
    }
    png_init_io(png, file);
    png_read_info(png, info);
    const int colorType = png_get_color_type(png, info);
    const int depth = png_get_bit_depth(png, info);
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (colorType & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    png_read_update_info(png, info);
    const int width = static_cast<int>(png_get_image_width(png, info));
    const int height = static_cast<int>(png_get_image_height(png, info));
    const int channels = png_get_channels(png, info);
    const int bits = png_get_bit_depth(png, info) == 16 ? 16 : 8;
    const std::size_t rowBytes = png_get_rowbytes(png, info);
    pixels.resize(rowBytes * static_cast<std::size_t>(height));
    rows.resize(static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
        rows[static_cast<std::size_t>(y)] = pixels.data() + rowBytes * static_cast<std::size_t>(y);
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(file);

    image.width = width;
    image.height = height;
    image.bits = bits;
    image.values.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    const std::size_t step = static_cast<std::size_t>(channels) * (bits == 16 ? 2 : 1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const unsigned char* p = rows[static_cast<std::size_t>(y)] + step * static_cast<std::size_t>(x);
            image.values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
                bits == 16 ? static_cast<std::uint16_t>((p[0] << 8) | p[1]) : p[0];
        }
    return image;
}

}  // namespace prism::bluenoise
