// PNG files for 8-bit RGBA images (golden images, galleries, contact sheets).
//
// Usage (snippet: examples/snippets/image_png_io.cpp):
//
//     #include "prism/image/png_io.hpp"
//     prism::image::writePng("out/phong.png", image);  // atomic: temp file + rename
//     prism::image::Image8 golden = prism::image::readPng("tests/golden/phong.png");
//
// writePng creates missing parent directories and never leaves a half-written file
// under the final name: it writes `<path>.tmp-<pid>` and renames it (and removes the
// temp files of earlier writers that were killed, whose process no longer exists). Any failure
// throws prism::image::PngError whose message names the file and the reason. readPng
// converts every PNG flavour (grey, palette, 16-bit, no alpha) to 8-bit RGBA, and
// refuses images over kMaxPngSide a side or kMaxPngPixels in all.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "prism/image/image.hpp"

namespace prism::image {

// readPng refuses images past these sizes before allocating them (docs/reliability.md).
inline constexpr std::uint32_t kMaxPngSide = 16384;
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t{1} << 26;

class PngError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

void writePng(const std::filesystem::path& path, const Image8& image);
Image8 readPng(const std::filesystem::path& path);

}  // namespace prism::image
