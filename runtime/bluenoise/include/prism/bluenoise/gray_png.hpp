// Grey PNG files of 8 or 16 bits for masks, and atomic writes of any text or bytes.
//
// Usage (snippet: examples/snippets/bluenoise_gray_png.cpp):
//
//     #include "prism/bluenoise/gray_png.hpp"
//     prism::bluenoise::GrayImage image{4, 4, 16, std::vector<std::uint16_t>(16, 40000)};
//     prism::bluenoise::writeGrayPng("out/mask.png", image);  // temp file + rename
//     prism::bluenoise::GrayImage back = prism::bluenoise::readGrayPng("out/mask.png");
//     prism::bluenoise::writeFileAtomically("out/spectrum.svg", "<svg/>");
//
// Writes are atomic (`<path>.tmp-<pid>` then rename), create missing parent directories
// and leave an existing file untouched when its bytes would not change. readGrayPng
// keeps 8 and 16 bits; colour files are reduced to their red channel, alpha is dropped,
// palettes and 1/2/4-bit greys are expanded to 8 bits. Failures throw
// std::runtime_error naming the file and the reason.
#pragma once

#include <filesystem>
#include <string_view>

#include "prism/bluenoise/metrics.hpp"

namespace prism::bluenoise {

void writeGrayPng(const std::filesystem::path& path, const GrayImage& image);
GrayImage readGrayPng(const std::filesystem::path& path);
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace prism::bluenoise
