// CPU images: RGBA pixels in memory, row 0 at the TOP (as in PNG files and on screen).
//
// Usage (snippet: examples/snippets/image_image.cpp):
//
//     #include "prism/image/image.hpp"
//     prism::image::Image8 img(64, 32, {255, 0, 0, 255});  // 64x32, opaque red
//     img.set(3, 4, {0, 0, 255, 255});                     // x = 3, y = 4 (4th row from the top)
//     prism::image::Rgba8 p = img.at(3, 4);
//     std::uint8_t* raw = img.data.data();  // width*height*4 bytes, row-major
//
//     prism::image::ImageF hdr(8, 8);  // float RGBA, zero-filled
//     hdr.set(0, 0, {1.5f, 0.f, 0.f, 1.f});
//     std::size_t bad = prism::image::countNonFinite(hdr);     // pixels holding NaN or infinity
//     prism::image::Image8 ldr = prism::image::toImage8(hdr);  // clamped to [0,1], NaN -> 0
//
// Both image types are plain values (copyable, comparable with ==). Coordinates outside
// the image are a programming error: at()/set() check them and throw std::out_of_range.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism::image {

using Rgba8 = std::array<std::uint8_t, 4>;
using RgbaF = std::array<float, 4>;

// An RGBA image with four channels of type T per pixel, rows top to bottom.
template <class T>
struct BasicImage {
    using Channel = T;
    using Pixel = std::array<T, 4>;
    static constexpr int kChannels = 4;

    int width = 0;
    int height = 0;
    std::vector<T> data;  // width * height * 4 channels, row-major, row 0 = top

    BasicImage() = default;
    BasicImage(int w, int h, Pixel fill = {}) : width(w), height(h) {
        if (w < 0 || h < 0)
            throw std::invalid_argument("prism::Image: negative size " + std::to_string(w) + "x" + std::to_string(h));
        data.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * kChannels);
        for (std::size_t i = 0; i < data.size(); i += kChannels)
            for (int c = 0; c < kChannels; ++c)
                data[i + static_cast<std::size_t>(c)] = fill[static_cast<std::size_t>(c)];
    }

    std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    bool empty() const { return pixelCount() == 0; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }

    // Index of channel 0 of pixel (x, y) in `data`; no bounds check.
    std::size_t offset(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
               kChannels;
    }

    Pixel at(int x, int y) const {
        check(x, y);
        const std::size_t o = offset(x, y);
        return {data[o], data[o + 1], data[o + 2], data[o + 3]};
    }

    void set(int x, int y, const Pixel& p) {
        check(x, y);
        const std::size_t o = offset(x, y);
        for (std::size_t c = 0; c < kChannels; ++c) data[o + c] = p[c];
    }

    friend bool operator==(const BasicImage&, const BasicImage&) = default;

  private:
    void check(int x, int y) const {
        if (!contains(x, y))
            throw std::out_of_range("prism::Image: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                    ") is outside the " + std::to_string(width) + "x" + std::to_string(height) +
                                    " image");
    }
};

using Image8 = BasicImage<std::uint8_t>;
using ImageF = BasicImage<float>;

// Number of pixels with at least one channel that is NaN or infinite.
std::size_t countNonFinite(const ImageF& image);

// Converts to 8 bits per channel: clamps to [0, 1], maps NaN to 0, rounds to nearest.
Image8 toImage8(const ImageF& image);

// Converts to float channels in [0, 1] (value / 255).
ImageF toImageF(const Image8& image);

// The image upside down (row 0 becomes the last row); used for GL readbacks.
template <class T>
BasicImage<T> flippedVertically(const BasicImage<T>& image) {
    BasicImage<T> out = image;
    const std::size_t row = static_cast<std::size_t>(image.width) * BasicImage<T>::kChannels;
    for (int y = 0; y < image.height; ++y)
        std::copy_n(
            image.data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row), row,
            out.data.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(image.height - 1 - y) * row));
    return out;
}

}  // namespace prism::image
