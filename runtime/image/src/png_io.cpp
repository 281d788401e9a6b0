// PNG reading and atomic writing with libpng's simplified API.
#include "prism/io/atomic_output.hpp"
#include "prism/image/png_io.hpp"

#include <png.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

namespace prism::image {
namespace {

std::string quoted(const std::filesystem::path& p) {
    std::string out(1, '\'');  // built piecewise: `"'" + string&&` trips GCC 12's -Wrestrict (PR 105329)
    out += p.string();
    out += '\'';
    return out;
}

}  // namespace

void writePng(const std::filesystem::path& path, const Image8& image) {
    if (image.empty())
        throw PngError("cannot write PNG " + quoted(path) + ": the image is empty (" + std::to_string(image.width) +
                       "x" + std::to_string(image.height) + ")");

    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec)
            throw PngError("cannot write PNG " + quoted(path) + ": cannot create directory " +
                           quoted(path.parent_path()) + ": " + ec.message());
    }

    io::removeStaleTemps(path, ".tmp-");
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid());

    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGBA;
    // Written through our own FILE so that a full disk or a read-only directory is
    // reported with its errno (libpng alone says only "Write Error").
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file)
        throw PngError("cannot write PNG " + quoted(path) + ": " + std::strerror(errno) +
                       " (check that the directory is writable)");
    errno = 0;
    bool ok = png_image_write_to_stdio(&png, file, 0, image.data.data(), static_cast<png_int_32>(image.width * 4),
                                       nullptr) != 0;
    int error = ok ? 0 : errno;
    if (std::fflush(file) != 0 || std::ferror(file)) {
        ok = false;
        error = error ? error : errno;
    }
    if (std::fclose(file) != 0) {
        ok = false;
        error = error ? error : errno;
    }
    const std::string reason = error ? std::string(std::strerror(error)) : std::string(png.message);
    png_image_free(&png);
    if (!ok) {
        std::filesystem::remove(temp, ec);
        throw PngError("cannot write PNG " + quoted(path) + ": " + (reason.empty() ? "libpng failed" : reason) +
                       (error == ENOSPC ? " (free some disk space)" : " (check that the directory is writable)"));
    }

    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw PngError("cannot write PNG " + quoted(path) + ": rename from " + quoted(temp) +
                       " failed: " + ec.message());
    }
}

Image8 readPng(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw PngError("cannot read PNG " + quoted(path) + ": no such file");

    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str())) {
        const std::string reason = png.message;
        png_image_free(&png);
        throw PngError("cannot read PNG " + quoted(path) + ": " + reason);
    }
    if (png.width > kMaxPngSide || png.height > kMaxPngSide ||
        static_cast<std::uint64_t>(png.width) * png.height > kMaxPngPixels) {
        png_image_free(&png);
        throw PngError("cannot read PNG " + quoted(path) + ": " + std::to_string(png.width) + "x" +
                       std::to_string(png.height) + " pixels is past the limit (" + std::to_string(kMaxPngSide) +
                       " a side, " + std::to_string(kMaxPngPixels) + " in all)");
    }
    png.format = PNG_FORMAT_RGBA;
    Image8 image(static_cast<int>(png.width), static_cast<int>(png.height));
    if (!png_image_finish_read(&png, nullptr, image.data.data(), static_cast<png_int_32>(image.width * 4), nullptr)) {
        const std::string reason = png.message;
        png_image_free(&png);
        throw PngError("cannot read PNG " + quoted(path) + ": " + reason);
    }
    return image;
}

}  // namespace prism::image
