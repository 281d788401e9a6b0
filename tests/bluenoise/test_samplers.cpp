// CPU samplers: integer-exact temporal offsets (frame 10^6 as precise as frame 0), blue
// noise per frame, well-spread per-pixel sequences, white noise uncorrelated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/samplers.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {
const bn::SamplerTables& tables64() {
    static const bn::SamplerTables t =
        bn::SamplerTables::fromMask(bn::generateVoidAndCluster({.width = 64, .height = 64}));
    return t;
}

bn::GrayImage frameImage(bn::SamplerKind kind, std::uint32_t frame, std::uint32_t dim) {
    bn::GrayImage image{64, 64, 16, {}};
    for (std::uint32_t y = 0; y < 64; ++y)
        for (std::uint32_t x = 0; x < 64; ++x)
            image.values.push_back(static_cast<std::uint16_t>(bn::sample(kind, tables64(), x, y, frame, dim) >> 16));
    return image;
}
}  // namespace

TEST(Samplers, BlueNoiseFramesStayBlueAtFrameMillion) {
    for (std::uint32_t frame : {0u, 1u, 1000000u})
        for (std::uint32_t dim : {0u, 3u}) {
            const bn::GrayImage image = frameImage(bn::SamplerKind::BlueNoise, frame, dim);
            EXPECT_TRUE(bn::histogramUniform(image)) << frame;
            // Thresholding a value-shifted slice selects the union of two blue threshold
            // sets: the dither quality (FAST) drops from the mask's 0.038 to 0.046..0.049 but
            // stays far below white noise's 0.114...
            EXPECT_LT(bn::filteredErrorSigma1(image), 0.055) << frame << " " << dim;
            // ...while the wrap of the values at 1 puts some low-frequency power into the
            // values themselves (0.0004 unshifted, up to ~0.08 shifted; white noise 1).
            EXPECT_LT(bn::lowFrequencyPowerRatio(image), 0.15) << frame << " " << dim;
            std::printf("frame %u dim %u: FAST %.4f LF %.4f\n", frame, dim, bn::filteredErrorSigma1(image),
                        bn::lowFrequencyPowerRatio(image));
        }
    const bn::GrayImage white = frameImage(bn::SamplerKind::White, 1000000u, 0);
    EXPECT_GT(bn::lowFrequencyPowerRatio(white), 0.7);
}

TEST(Samplers, TemporalOffsetIsExactInteger) {
    // Frame f differs from frame 0 by exactly f * step mod 2^32 at every pixel, with the
    // step 2^32/phi for even dimensions and 2^32 (sqrt(3) - 1) for odd ones.
    for (std::uint32_t frame : {1u, 1000000u, 0xFFFFFFFFu})
        for (std::uint32_t dim : {2u, 3u}) {
            const std::uint32_t step = dim == 2 ? 0x9E3779B9u : 0xBB67AE86u;
            const std::uint32_t a = bn::sample(bn::SamplerKind::BlueNoise, tables64(), 5, 9, 0, dim);
            const std::uint32_t b = bn::sample(bn::SamplerKind::BlueNoise, tables64(), 5, 9, frame, dim);
            EXPECT_EQ(static_cast<std::uint32_t>(b - a), static_cast<std::uint32_t>(frame * step));
            const std::uint32_t c = bn::sample(bn::SamplerKind::Sorted, tables64(), 5, 9, 0, dim);
            const std::uint32_t d = bn::sample(bn::SamplerKind::Sorted, tables64(), 5, 9, frame, dim);
            EXPECT_EQ(static_cast<std::uint32_t>(d - c), static_cast<std::uint32_t>(frame * step));
        }
}

TEST(Samplers, PerPixelSequenceIsWellSpread) {
    // 32 frames at one pixel: the golden-ratio sequence leaves no gap wider than 2/32 of
    // [0, 1); 32 white samples typically leave gaps several times wider.
    auto largestGap = [](bn::SamplerKind kind) {
        std::vector<double> v;
        for (std::uint32_t f = 0; f < 32; ++f) v.push_back(bn::toUnitFloat(bn::sample(kind, tables64(), 7, 3, f, 0)));
        std::sort(v.begin(), v.end());
        double gap = 1.0 - v.back() + v.front();
        for (std::size_t i = 1; i < v.size(); ++i) gap = std::max(gap, v[i] - v[i - 1]);
        return gap;
    };
    EXPECT_LT(largestGap(bn::SamplerKind::BlueNoise), 2.0 / 32.0);
    EXPECT_GT(largestGap(bn::SamplerKind::White), 2.0 / 32.0);
}

TEST(Samplers, TemporalStepsAreTheirIrrationals) {
    EXPECT_NEAR(bn::temporalStep(0) / 4294967296.0, 2.0 / (1.0 + std::sqrt(5.0)), 1e-9);
    EXPECT_NEAR(bn::temporalStep(1) / 4294967296.0, std::sqrt(3.0) - 1.0, 1e-9);
    EXPECT_EQ(bn::temporalStep(4), bn::temporalStep(0));
}

TEST(Samplers, DimensionsUseDifferentMaskOffsets) {
    std::uint32_t dx = 0, dy = 0;
    bn::r2Offset(0, 64, 64, dx, dy);
    EXPECT_EQ(dx, 0u);
    EXPECT_EQ(dy, 0u);
    int same = 0;
    for (std::uint32_t y = 0; y < 64; ++y)
        for (std::uint32_t x = 0; x < 64; ++x)
            same += bn::sample(bn::SamplerKind::BlueNoise, tables64(), x, y, 0, 0) ==
                    bn::sample(bn::SamplerKind::BlueNoise, tables64(), x, y, 0, 1);
    EXPECT_LT(same, 10);
    // Plastic number g: g^3 = g + 1, and the steps are 2^32/g, 2^32/g^2.
    const double g = 1.32471795724474602596;
    EXPECT_NEAR(g * g * g, g + 1.0, 1e-12);
    EXPECT_NEAR(bn::kR2StepX / 4294967296.0, 1.0 / g, 1e-9);
    EXPECT_NEAR(bn::kR2StepY / 4294967296.0, 1.0 / (g * g), 1e-9);
}

TEST(Samplers, PcgHashKnownValues) {
    // pcgHash(0) evaluated independently in Python (unbounded integers masked to 32 bits).
    EXPECT_EQ(bn::pcgHash(0u), 129708002u);
    EXPECT_NE(bn::pcgHash(1u), bn::pcgHash(2u));
    EXPECT_EQ(bn::toUnitFloat(0xFFFFFFFFu) < 1.0f, true);
}
