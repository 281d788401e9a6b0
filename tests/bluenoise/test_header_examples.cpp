// The usage examples at the top of every public header of prism/bluenoise/, compiled and
// run as written (keep them in step with the headers).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/mask.hpp"
#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/random.hpp"
#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/samplers.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/sorting.hpp"
#include "prism/bluenoise/spectrum_svg.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

TEST(HeaderExamples, Random) {
    std::uint32_t h = prism::bluenoise::pcgHash(42u);
    prism::bluenoise::SplitMix64 rng(7);
    std::uint64_t a = rng.next();
    double u = rng.uniform();
    float f = prism::bluenoise::toUnitFloat(h);
    EXPECT_NE(a, 0u);
    EXPECT_LT(u, 1.0);
    EXPECT_LT(f, 1.0f);
}

TEST(HeaderExamples, MaskAndVoidAndCluster) {
    prism::bluenoise::Mask mask = prism::bluenoise::generateVoidAndCluster({.width = 64, .height = 64});
    std::vector<std::uint16_t> png8 = prism::bluenoise::quantize(mask, 8);
    std::vector<std::uint32_t> fixed = prism::bluenoise::fixedPoint32(mask);
    std::uint32_t r = mask.rankAt(3, 5);
    EXPECT_EQ(png8.size(), fixed.size());
    EXPECT_LT(r, 4096u);

    prism::bluenoise::VoidAndClusterOptions options;
    options.width = 128;
    options.height = 64;
    options.sigma = 1.5;
    options.seed = 7;
    prism::bluenoise::Mask mask2 = prism::bluenoise::generateVoidAndCluster(options);
    EXPECT_EQ(mask2.size(), 128u * 64u);
}

TEST(HeaderExamples, Metrics) {
    prism::bluenoise::GrayImage image{2, 1, 8, {0, 255}};
    bool uniform = prism::bluenoise::histogramUniform(image);
    double lf = prism::bluenoise::lowFrequencyPowerRatio(image);
    double fast = prism::bluenoise::filteredErrorSigma1(image);
    double aniso = prism::bluenoise::anisotropyDb(image);
    std::vector<prism::bluenoise::SpectrumRing> rings = prism::bluenoise::radialPowerSpectrum(image);
    EXPECT_TRUE(uniform);  // 2 pixels: as even as 2 values over 256 levels can be
    EXPECT_TRUE(std::isfinite(lf + fast + aniso));
    EXPECT_FALSE(rings.empty());
}

TEST(HeaderExamples, GrayPngAndSvg) {
    const auto dir = std::filesystem::temp_directory_path() / ("prism_bn_examples_" + std::to_string(::getpid()));
    prism::bluenoise::GrayImage image{4, 4, 16, std::vector<std::uint16_t>(16, 40000)};
    prism::bluenoise::writeGrayPng(dir / "out/mask.png", image);
    prism::bluenoise::GrayImage back = prism::bluenoise::readGrayPng(dir / "out/mask.png");
    prism::bluenoise::writeFileAtomically(dir / "out/spectrum.svg", "<svg/>");
    EXPECT_EQ(back.values, image.values);

    std::vector<prism::bluenoise::SpectrumRing> rings = {{0.1, 0.2, 4}, {0.2, 1.1, 8}};
    std::string svg = prism::bluenoise::spectrumSvg({{"void-and-cluster 64x64", rings}});
    prism::bluenoise::PlotSeries s{"white", {{1, 0.3}, {4, 0.15}}};
    std::string plot = prism::bluenoise::linePlotSvg("frames", "RMS error", {s}, true);
    EXPECT_NE(svg.find("<polyline"), std::string::npos);
    EXPECT_NE(plot.find("white"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(HeaderExamples, Samplers) {
    namespace bn = prism::bluenoise;
    bn::SamplerTables tables = bn::SamplerTables::fromMask(bn::generateVoidAndCluster({.width = 64, .height = 64}));
    std::uint32_t w = bn::sample(bn::SamplerKind::White, tables, 10, 20, 7, 0);
    std::uint32_t b = bn::sample(bn::SamplerKind::BlueNoise, tables, 10, 20, 7, 1);
    float u = bn::toUnitFloat(b);
    EXPECT_NE(w, b);
    EXPECT_LT(u, 1.0f);
}

TEST(HeaderExamples, SortingAndRetarget) {
    namespace bn = prism::bluenoise;
    std::vector<std::uint32_t> seeds = bn::initialSeeds(8, 8, 1);
    std::vector<float> values(64, 0.5f);
    std::vector<std::uint32_t> target(64);
    for (std::uint32_t i = 0; i < 64; ++i) target[i] = i * 0x04000000u;
    bn::sortSeedsInBlocks(values, target, 8, 8, 4, seeds);

    bn::Mask mask = bn::generateVoidAndCluster({.width = 32, .height = 32});
    bn::RetargetOptions options;
    options.schedule = bn::CoolingSchedule::Exponential;
    options.epochs = 8;
    bn::RetargetResult r = bn::computeRetarget(mask, options);
    bool cached = false;
    const auto path =
        std::filesystem::temp_directory_path() / ("prism_bn_example_retarget_" + std::to_string(::getpid()) + ".bin");
    bn::RetargetPermutation p = bn::loadOrComputeRetarget(mask, options, path, &cached);
    EXPECT_EQ(p.source.size(), r.permutation.source.size());
    std::filesystem::remove(path);
}

TEST(HeaderExamples, SoftShadows) {
    namespace bn = prism::bluenoise;
    bn::SoftShadowScene scene = bn::SoftShadowScene::classic();
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 64, .height = 64}));
    bn::RenderOptions options;
    options.width = options.height = 64;
    options.sampler = bn::SamplerKind::BlueNoise;
    bn::RealImage image = bn::renderSoftShadows(scene, setup, options);
    bn::Reference reference = bn::renderReference(scene, 64, 64, 1024);
    bn::ErrorStats error = bn::compareToReference(image, reference);
    EXPECT_GT(error.pixels, 0);
}
