// The soft-shadow demo on the GPU (llvmpipe) against the double-precision CPU renderer:
// same sampler integers, float vs double geometry, so nearly every pixel agrees to 1e-3;
// a few pixels whose shadow ray grazes a sphere may flip.
#include <gtest/gtest.h>

#include <cmath>

#include "prism/bluenoise/gl_soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/test/gl_test.hpp"

namespace bn = prism::bluenoise;

class GlSoftShadows : public prism::test::GlTest {};

TEST_F(GlSoftShadows, MatchesTheCpuRenderer) {
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
    bn::RetargetOptions r;
    r.shiftX = setup.shiftX;
    r.shiftY = setup.shiftY;
    r.epochs = 4;
    setup.retarget = bn::computeRetarget(setup.mask, r).permutation;
    setup.tables.setStack(bn::generateSpatiotemporal({.width = 16, .height = 16}, 4));
    bn::GlSoftShadows gpu(48, 40);
    for (bn::SamplerKind kind :
         {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted, bn::SamplerKind::Stack}) {
        bn::RenderOptions o;
        o.width = 48;
        o.height = 40;
        o.sampler = kind;
        o.spp = 2;
        o.frames = 3;
        const bn::RealImage g = gpu.render(bn::SoftShadowScene::classic(), setup, o);
        const bn::RealImage c = bn::renderSoftShadows(bn::SoftShadowScene::classic(), setup, o);
        ASSERT_EQ(g.values.size(), c.values.size());
        int off = 0;
        double sum = 0.0;
        for (std::size_t i = 0; i < g.values.size(); ++i) {
            ASSERT_TRUE(std::isfinite(g.values[i]));
            const double d = std::abs(g.values[i] - c.values[i]);
            off += d > 1e-3;
            sum += d;
        }
        EXPECT_LE(off, static_cast<int>(g.values.size()) / 100) << "sampler " << static_cast<int>(kind);
        EXPECT_LT(sum / static_cast<double>(g.values.size()), 2e-3) << "sampler " << static_cast<int>(kind);
        EXPECT_GT(gpu.lastFrameMilliseconds(), 0.0);
    }
    bn::SoftShadowScene crowded = bn::SoftShadowScene::classic();
    crowded.spheres.push_back({0, 0, 0.5, 0.1});
    bn::RenderOptions o;
    o.width = 48;
    o.height = 40;
    EXPECT_THROW(gpu.render(crowded, setup, o), std::invalid_argument);
}

TEST(HeaderExamples, GlSoftShadows) {  // the usage example of prism/bluenoise/gl_soft_shadows.hpp
    namespace bn = prism::bluenoise;
    auto context = prism::gl::createContext();
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 64, .height = 64}));
    bn::RenderOptions options;
    options.width = options.height = 64;
    options.sampler = bn::SamplerKind::BlueNoise;
    bn::GlSoftShadows gpu(64, 64);
    bn::RealImage image = gpu.render(bn::SoftShadowScene::classic(), setup, options);
    double ms = gpu.lastFrameMilliseconds();
    EXPECT_EQ(image.values.size(), 64u * 64u);
    EXPECT_GT(ms, 0.0);
}
