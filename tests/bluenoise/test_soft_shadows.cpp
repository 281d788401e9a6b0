// Soft shadows rendered with the three samplers against a 1024-spp reference: the
// acceptance numbers of issue 13 (1 spp one frame, 32 frames accumulated, the sorting
// pass alone) and the extremes (all-black and all-white scenes, frame 10^6).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {

constexpr int kSize = 128;

const bn::Reference& reference() {
    static const bn::Reference r = bn::renderReference(bn::SoftShadowScene::classic(), kSize, kSize, 1024);
    return r;
}

bn::StochasticSetup& setup() {
    static bn::StochasticSetup s = [] {
        bn::StochasticSetup made = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 128, .height = 128}));
        bn::RetargetOptions o;
        o.shiftX = made.shiftX;
        o.shiftY = made.shiftY;
        o.epochs = 16;
        made.retarget = bn::computeRetarget(made.mask, o).permutation;
        return made;
    }();
    return s;
}

bn::ErrorStats errorOf(bn::SamplerKind sampler, int frames, int frame = 0, bool aPosteriori = false, int block = 8) {
    bn::RenderOptions o;
    o.width = o.height = kSize;
    o.sampler = sampler;
    o.frames = frames;
    o.frame = frame;
    o.aPosteriori = aPosteriori;
    o.block = block;
    const bn::ErrorStats e =
        bn::compareToReference(bn::renderSoftShadows(bn::SoftShadowScene::classic(), setup(), o), reference());
    std::printf("sampler %d frames %d frame %d aposteriori %d block %d: rms %.5f blurred %.5f lf %.4f (%d px)\n",
                static_cast<int>(sampler), frames, frame, aPosteriori, block, e.rms, e.blurredRms, e.lowFrequencyRatio,
                e.pixels);
    return e;
}

}  // namespace

TEST(SoftShadows, ReferenceTouchesThePenumbrae) {
    EXPECT_GT(reference().touched.size(), 0u);
    int touched = 0;
    for (char t : reference().touched) touched += t;
    EXPECT_GT(touched, kSize * kSize / 20);
    EXPECT_LT(touched, kSize * kSize / 2);
    std::printf("penumbra pixels: %d of %d\n", touched, kSize * kSize);
}

TEST(SoftShadows, OneSppOneFrameBlueNoiseBeatsWhite) {
    const bn::ErrorStats white = errorOf(bn::SamplerKind::White, 1);
    const bn::ErrorStats blue = errorOf(bn::SamplerKind::BlueNoise, 1);
    EXPECT_LE(blue.blurredRms, 0.5 * white.blurredRms);
    EXPECT_LE(blue.lowFrequencyRatio, 0.3 * white.lowFrequencyRatio);
}

TEST(SoftShadows, ThirtyTwoFramesAccumulated) {
    const bn::ErrorStats white = errorOf(bn::SamplerKind::White, 32);
    const bn::ErrorStats blue = errorOf(bn::SamplerKind::BlueNoise, 32);
    EXPECT_LE(blue.rms, 0.35 * white.rms);
    EXPECT_LE(blue.blurredRms, 0.25 * white.blurredRms);
    const bn::ErrorStats sorted = errorOf(bn::SamplerKind::Sorted, 32);
    EXPECT_LT(sorted.rms, white.rms * 1.2);
}

TEST(SoftShadows, SortingPassAloneOnAStaticScene) {
    const bn::ErrorStats white = errorOf(bn::SamplerKind::White, 1);
    const bn::ErrorStats sorted8 = errorOf(bn::SamplerKind::Sorted, 1, 0, true, 8);
    const bn::ErrorStats sorted4 = errorOf(bn::SamplerKind::Sorted, 1, 0, true, 4);
    EXPECT_GE(white.blurredRms / sorted8.blurredRms, 1.4);
    EXPECT_GE(white.blurredRms / sorted4.blurredRms, 1.1);
}

TEST(SoftShadows, FrameMillionIsAsGoodAsFrameZero) {
    const bn::ErrorStats zero = errorOf(bn::SamplerKind::BlueNoise, 1, 0);
    const bn::ErrorStats million = errorOf(bn::SamplerKind::BlueNoise, 1, 1000000);
    EXPECT_LT(million.blurredRms, 1.3 * zero.blurredRms);
    EXPECT_GT(million.blurredRms, 0.7 * zero.blurredRms);
}

TEST(SoftShadows, BlackAndWhiteScenesAreFinite) {
    for (const bn::SoftShadowScene& scene : {bn::SoftShadowScene::black(), bn::SoftShadowScene::white()}) {
        const bn::Reference ref = bn::renderReference(scene, 32, 32, 64);
        for (char t : ref.touched) EXPECT_FALSE(t);  // no penumbra anywhere
        for (bn::SamplerKind kind : {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted}) {
            bn::RenderOptions o;
            o.width = o.height = 32;
            o.sampler = kind;
            o.frames = 3;
            const bn::RealImage image = bn::renderSoftShadows(scene, setup(), o);
            for (double v : image.values) {
                ASSERT_TRUE(std::isfinite(v));
                ASSERT_GE(v, 0.0);
            }
            const bn::ErrorStats e = bn::compareToReference(image, ref);
            EXPECT_EQ(e.pixels, 0);
            EXPECT_EQ(e.rms, 0.0);
            EXPECT_TRUE(std::isfinite(e.lowFrequencyRatio));
        }
    }
    // The black scene is exactly 0; the white one at least 1 (white on display).
    bn::RenderOptions o;
    o.width = o.height = 16;
    for (double v : bn::renderSoftShadows(bn::SoftShadowScene::black(), setup(), o).values) EXPECT_EQ(v, 0.0);
    for (double v : bn::renderSoftShadows(bn::SoftShadowScene::white(), setup(), o).values) EXPECT_GE(v, 1.0);
}

TEST(SoftShadows, BadOptionsThrow) {
    bn::RenderOptions o;
    o.spp = 0;
    EXPECT_THROW(bn::renderSoftShadows(bn::SoftShadowScene::classic(), setup(), o), std::invalid_argument);
    o.spp = 1;
    o.frames = 0;
    EXPECT_THROW(bn::renderSoftShadows(bn::SoftShadowScene::classic(), setup(), o), std::invalid_argument);
}

TEST(SoftShadows, SpatiotemporalStackSampler) {
    // A 64x64x32 stack tiled over the image: every frame blue, and over 32 frames each
    // pixel has seen 32 well-spread values.
    bn::StochasticSetup stackSetup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 64, .height = 64}));
    stackSetup.tables.setStack(bn::generateSpatiotemporal({.width = 64, .height = 64}, 32));
    auto error = [&](bn::SamplerKind kind, int frames) {
        bn::RenderOptions o;
        o.width = o.height = kSize;
        o.sampler = kind;
        o.frames = frames;
        const bn::ErrorStats e =
            bn::compareToReference(bn::renderSoftShadows(bn::SoftShadowScene::classic(), stackSetup, o), reference());
        std::printf("sampler %d frames %d: rms %.5f blurred %.5f lf %.4f\n", static_cast<int>(kind), frames, e.rms,
                    e.blurredRms, e.lowFrequencyRatio);
        return e;
    };
    const bn::ErrorStats white1 = error(bn::SamplerKind::White, 1), stack1 = error(bn::SamplerKind::Stack, 1);
    const bn::ErrorStats white32 = error(bn::SamplerKind::White, 32), stack32 = error(bn::SamplerKind::Stack, 32);
    EXPECT_LE(stack1.blurredRms, 0.5 * white1.blurredRms);
    EXPECT_LE(stack32.rms, 0.6 * white32.rms);
    EXPECT_LE(stack32.blurredRms, 0.5 * white32.blurredRms);
    error(bn::SamplerKind::BlueNoise, 32);  // for comparison in the log
}
