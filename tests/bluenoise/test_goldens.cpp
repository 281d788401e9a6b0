// Golden images of the soft-shadow demo with the three samplers (tests/golden/bluenoise/,
// 64x64, 1 spp, frame 2; PRISM_UPDATE_GOLDENS=1 rewrites them). Threshold: every pixel
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

std::string goldenPath(const char* name) {
    return std::string(PRISM_BLUENOISE_GOLDEN_DIR) + "/" + name + ".png";
}

// Empty when within the threshold, else what differs.
std::string compare(const bn::GrayImage& image, const bn::GrayImage& golden) {
    if (image.width != golden.width || image.height != golden.height) return "size differs";
    int off = 0, worst = 0;
    for (std::size_t i = 0; i < image.values.size(); ++i) {
        const int d = std::abs(static_cast<int>(image.values[i]) - static_cast<int>(golden.values[i]));
        worst = std::max(worst, d);
        off += d > 0;
    }
    if (worst <= 1 && off * 200 <= static_cast<int>(image.values.size())) return "";
    return std::to_string(off) + " pixels differ, by up to " + std::to_string(worst) + " levels";
}

const std::pair<bn::SamplerKind, const char*> kSamplers[] = {
    {bn::SamplerKind::White, "white"}, {bn::SamplerKind::BlueNoise, "bluenoise"}, {bn::SamplerKind::Sorted, "sorted"}};

}  // namespace

TEST(Goldens, ThreeSamplersMatchTheirGoldens) {
    const bool update = std::getenv("PRISM_UPDATE_GOLDENS") != nullptr;
    for (const auto& [kind, name] : kSamplers) {
        const bn::GrayImage image = render(kind, 2);
        if (update) bn::writeGrayPng(goldenPath(name), image);
        EXPECT_EQ(compare(image, bn::readGrayPng(goldenPath(name))), "") << name;
    }
}

TEST(Goldens, MutationsAreCaught) {
    const bn::GrayImage white = bn::readGrayPng(goldenPath("white"));
    const bn::GrayImage blue = bn::readGrayPng(goldenPath("bluenoise"));
    EXPECT_NE(compare(render(bn::SamplerKind::BlueNoise, 2), white), "");  // another sampler
    EXPECT_NE(compare(render(bn::SamplerKind::BlueNoise, 3), blue), "");   // another frame
    bn::GrayImage oneLevel = blue;                                         // within the threshold
    oneLevel.values[100] = static_cast<std::uint16_t>(oneLevel.values[100] == 255 ? 254 : oneLevel.values[100] + 1);
    EXPECT_EQ(compare(oneLevel, blue), "");
    oneLevel.values[101] = static_cast<std::uint16_t>(oneLevel.values[101] > 128 ? 0 : 255);  // beyond it
    EXPECT_NE(compare(oneLevel, blue), "");
}
