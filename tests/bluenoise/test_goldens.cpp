// Golden images of the soft-shadow demo with the three samplers (tests/golden/bluenoise/,
// 64x64, 1 spp, frame 2; the check and its update mode: prism/test/golden.hpp). Threshold: every pixel
// within 1 level of 255 and at most 0.5% of pixels off by that one level (float
// rounding across compilers). The mutation tests show the comparison catches another
// sampler and another frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
#include "prism/test/golden.hpp"

namespace bn = prism::bluenoise;

namespace {

bn::GrayImage render(bn::SamplerKind kind, int frame) {
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
    bn::RetargetOptions r;
    r.shiftX = setup.shiftX;
    r.shiftY = setup.shiftY;
    r.epochs = 4;
    setup.retarget = bn::computeRetarget(setup.mask, r).permutation;
    bn::RenderOptions o;
    o.width = o.height = 64;
    o.sampler = kind;
    o.frame = frame;
    const bn::RealImage image = bn::renderSoftShadows(bn::SoftShadowScene::classic(), setup, o);
    bn::GrayImage out{64, 64, 8, {}};
    for (double v : image.values)
        out.values.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)));
    return out;
}

// The 8-bit image as the comparator reads it (grey in R, G and B, opaque), as readPng reads
// the grey goldens.
prism::image::Image8 asImage8(const bn::GrayImage& gray) {
    prism::image::Image8 out(gray.width, gray.height, {0, 0, 0, 255});
    for (std::size_t i = 0; i < gray.values.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c) out.data[i * 4 + c] = static_cast<std::uint8_t>(gray.values[i]);
    return out;
}

// Every pixel within 1 level, and at most 0.5 % of the pixels off at all.
constexpr prism::image::Thresholds kThresholds{
    .maxChannelDiff = 0, .maxShareOver = 0.005, .maxMean = 1.0, .maxPixelDiff = 1};

prism::test::GoldenCheck golden(const char* name) {
    return {.golden = std::string(PRISM_BLUENOISE_GOLDEN_DIR) + "/" + name + ".png",
            .outName = std::string("bluenoise/") + name,
            .thresholds = kThresholds,
            .outDir = PRISM_BLUENOISE_GOLDEN_FAILURE_DIR};
}

const std::pair<bn::SamplerKind, const char*> kSamplers[] = {
    {bn::SamplerKind::White, "white"}, {bn::SamplerKind::BlueNoise, "bluenoise"}, {bn::SamplerKind::Sorted, "sorted"}};

}  // namespace

TEST(Goldens, ThreeSamplersMatchTheirGoldens) {
    for (const auto& [kind, name] : kSamplers)
        prism::test::expectMatchesGolden(asImage8(render(kind, 2)), golden(name));
}

TEST(Goldens, MutationsAreCaught) {
    prism::test::expectFailsGolden(asImage8(render(bn::SamplerKind::BlueNoise, 2)), golden("white"),
                                   "blue noise against white's golden");
    prism::test::expectFailsGolden(asImage8(render(bn::SamplerKind::BlueNoise, 3)), golden("bluenoise"), "frame 3");
    const bn::GrayImage blue = bn::readGrayPng(golden("bluenoise").golden.string());
    bn::GrayImage oneLevel = blue;  // within the threshold
    oneLevel.values[100] = static_cast<std::uint16_t>(oneLevel.values[100] == 255 ? 254 : oneLevel.values[100] + 1);
    EXPECT_EQ(prism::test::compareWithGolden(asImage8(oneLevel), golden("bluenoise")).outcome,
              prism::test::GoldenOutcome::Matches);
    oneLevel.values[101] = static_cast<std::uint16_t>(oneLevel.values[101] > 128 ? 0 : 255);  // beyond it
    prism::test::expectFailsGolden(asImage8(oneLevel), golden("bluenoise"), "one pixel off by more than a level");
}
