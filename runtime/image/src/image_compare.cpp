// Statistics and difference image for golden-image comparison.
#include "prism/image/image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace prism::image {
namespace {

std::string sizeText(const Image8& img) {
    return std::to_string(img.width) + "x" + std::to_string(img.height);
}

}  // namespace

std::size_t ImageComparison::pixelsAbove(int threshold) const {
    std::size_t n = 0;
    for (int d = std::max(threshold + 1, 0); d < 256; ++d) n += maxDiffHistogram[static_cast<std::size_t>(d)];
    return n;
}

ImageComparison compareImages(const Image8& actual, const Image8& expected, int channelThreshold) {
    ImageComparison out;
    out.channelThreshold = channelThreshold;
    if (actual.width != expected.width || actual.height != expected.height) {
        out.sizeMessage = "size differs: actual " + sizeText(actual) + ", expected " + sizeText(expected);
        return out;
    }
    out.sizeMatches = true;
    out.width = actual.width;
    out.height = actual.height;
    out.diff = Image8(actual.width, actual.height, {0, 0, 0, 255});

    std::uint64_t sumAbs = 0;
    for (std::size_t o = 0; o < actual.data.size(); o += 4) {
        int d[4];
        int pixelMax = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            d[c] = std::abs(int(actual.data[o + c]) - int(expected.data[o + c]));
            sumAbs += static_cast<std::uint64_t>(d[c]);
            pixelMax = std::max(pixelMax, d[c]);
        }
        ++out.maxDiffHistogram[static_cast<std::size_t>(pixelMax)];
        out.maxChannelDiff = std::max(out.maxChannelDiff, pixelMax);
        for (std::size_t c = 0; c < 3; ++c)
            out.diff.data[o + c] = static_cast<std::uint8_t>(std::min(255, std::max(d[c], d[3]) * 8));
    }
    out.pixelsOver = out.pixelsAbove(channelThreshold);
    const std::size_t pixels = actual.pixelCount();
    if (pixels > 0) {
        out.shareOver = static_cast<double>(out.pixelsOver) / static_cast<double>(pixels);
        out.meanAbsError = static_cast<double>(sumAbs) / static_cast<double>(pixels * 4);
    }
    return out;
}

bool passes(const ImageComparison& stats, const Thresholds& t) {
    if (!stats.sizeMatches) return false;
    const std::size_t pixels = static_cast<std::size_t>(stats.width) * static_cast<std::size_t>(stats.height);
    const double share =
        pixels > 0 ? static_cast<double>(stats.pixelsAbove(t.maxChannelDiff)) / static_cast<double>(pixels) : 0.0;
    return share <= t.maxShareOver && stats.meanAbsError <= t.maxMean && stats.maxChannelDiff <= t.maxPixelDiff;
}

std::string describe(const ImageComparison& stats, const Thresholds& t) {
    if (!stats.sizeMatches) return stats.sizeMessage;
    const std::size_t pixels = static_cast<std::size_t>(stats.width) * static_cast<std::size_t>(stats.height);
    const std::size_t over = stats.pixelsAbove(t.maxChannelDiff);
    const double share = pixels > 0 ? static_cast<double>(over) / static_cast<double>(pixels) : 0.0;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%s: max channel diff %d; %zu of %zu pixels (%.4f%%, allowed %.4f%%) differ by more than %d; "
                  "mean abs error %.4f (allowed %.4f)",
                  passes(stats, t) ? "pass" : "FAIL", stats.maxChannelDiff, over, pixels, share * 100.0,
                  t.maxShareOver * 100.0, t.maxChannelDiff, stats.meanAbsError, t.maxMean);
    std::string text = buf;
    if (t.maxPixelDiff < 255) text += "; no pixel may differ by more than " + std::to_string(t.maxPixelDiff);
    return text;
}

}  // namespace prism::image
