// Golden-image comparison of 8-bit RGBA images: statistics, pass/fail thresholds
// and an amplified difference image.
//
// Usage (snippet: examples/snippets/image_image_compare.cpp):
//
//     #include <iostream>
//
//     #include "prism/image/image_compare.hpp"
//     #include "prism/image/png_io.hpp"
//     prism::image::ImageComparison cmp = prism::image::compareImages(actual, golden);
//     prism::image::Thresholds t{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};
//     if (!prism::image::passes(cmp, t)) {
//         std::cerr << prism::image::describe(cmp, t) << "\n";
//         prism::image::writePng("out/phong.diff.png", cmp.diff);
//     }
//
// A pixel is "over" when its largest channel difference exceeds t.maxChannelDiff;
// the comparison passes when the sizes match, the share of over pixels is at most
// t.maxShareOver, the mean absolute error (8-bit units, all four channels of all
// pixels) is at most t.maxMean and no pixel differs by more than t.maxPixelDiff. The
// stats keep a histogram of per-pixel maximum differences, so passes() and describe()
// work for any threshold afterwards.
// Mesa llvmpipe is byte-exact across runs; a few units on a tiny share of pixels
// absorbs technique or driver changes (docs/references.md, "Golden-image testing").
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "prism/image/image.hpp"

namespace prism::image {

struct Thresholds {
    int maxChannelDiff = 3;       // per channel, 8-bit units; a pixel above this is "over"
    double maxShareOver = 0.001;  // allowed share (0..1) of over pixels
    double maxMean = 0.5;         // allowed mean absolute error, 8-bit units
    int maxPixelDiff = 255;       // no pixel's largest channel difference may exceed this
};

struct ImageComparison {
    bool sizeMatches = false;
    std::string sizeMessage;  // e.g. "size differs: actual 64x64, expected 64x32"; empty when sizes match
    int width = 0;            // of the compared area (= both sizes when they match)
    int height = 0;
    int maxChannelDiff = 0;                           // largest |actual - expected| over all channels and pixels
    std::size_t pixelsOver = 0;                       // pixels whose max channel diff exceeds `channelThreshold`
    double shareOver = 0.0;                           // pixelsOver / pixel count (0 for empty images)
    int channelThreshold = 0;                         // the threshold pixelsOver was counted with
    double meanAbsError = 0.0;                        // mean of |d| over all channels of all pixels, 8-bit units
    std::array<std::size_t, 256> maxDiffHistogram{};  // pixels per per-pixel max channel diff
    Image8 diff;  // |d| * 8 clamped per RGB channel (alpha diff folded in), alpha 255

    // Pixels whose max channel diff exceeds `threshold`, from the histogram.
    std::size_t pixelsAbove(int threshold) const;
};

// Compares actual with expected; pixelsOver/shareOver are counted with `channelThreshold`.
// Images of different sizes give sizeMatches = false and no pixel statistics.
ImageComparison compareImages(const Image8& actual, const Image8& expected, int channelThreshold = 3);

bool passes(const ImageComparison& stats, const Thresholds& thresholds);

// One line for test failures: sizes or stats against the thresholds.
std::string describe(const ImageComparison& stats, const Thresholds& thresholds);

}  // namespace prism::image
