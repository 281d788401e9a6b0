// Off-screen framebuffers: exact clear colours, float targets, and readback with row 0
// at the top, on each backend that draws off screen (EGL and OSMesa).
#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"

#include <string>
#include <type_traits>

// The backends a framebuffer is tested on, named as CTest shows them (FramebufferTest.X<offscreen::Egl>).
namespace offscreen {
struct Egl : std::integral_constant<prism::gl::Backend, prism::gl::Backend::Egl> {};
struct OsMesa : std::integral_constant<prism::gl::Backend, prism::gl::Backend::OsMesa> {};
}  // namespace offscreen

namespace {

using prism::gl::ColorFormat;
using prism::gl::Framebuffer;

template <class OnBackend>
class FramebufferTest : public prism::test::GlTestOn<OnBackend::value> {};

using OffScreenBackends = ::testing::Types<offscreen::Egl, offscreen::OsMesa>;
TYPED_TEST_SUITE(FramebufferTest, OffScreenBackends);

TYPED_TEST(FramebufferTest, RunsOnTheBackendItNames) {
    EXPECT_EQ(TestFixture::context().backend(), TypeParam::value);
}

TYPED_TEST(FramebufferTest, ClearReadsBackExactColour) {
    Framebuffer fb(prism::test::kSize, 48);
    fb.clear({51.f / 255.f, 102.f / 255.f, 153.f / 255.f, 204.f / 255.f});
    const prism::image::Image8 img = fb.readImage8();
    ASSERT_EQ(img.width, prism::test::kSize);
    ASSERT_EQ(img.height, 48);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            ASSERT_EQ(img.at(x, y), (prism::image::Rgba8{51, 102, 153, 204})) << "at " << x << "," << y;
}

TYPED_TEST(FramebufferTest, FloatTargetKeepsValuesOutsideZeroToOne) {
    Framebuffer fb(8, 8, ColorFormat::Rgba32F);
    fb.clear({2.5f, -0.75f, 0.125f, 1.0f});
    const prism::image::ImageF img = fb.readImageF();
    EXPECT_EQ(img.at(3, 5), (prism::image::RgbaF{2.5f, -0.75f, 0.125f, 1.0f}));
    EXPECT_EQ(prism::image::countNonFinite(img), 0u);
    // The 8-bit read of a float target clamps.
    EXPECT_EQ(fb.readImage8().at(0, 0), (prism::image::Rgba8{255, 0, 32, 255}));
}

TYPED_TEST(FramebufferTest, RowZeroIsTheTop) {
    Framebuffer fb(16, 16);
    fb.clear({0.f, 0.f, 1.f, 1.f});
    // GL's y runs upwards: the scissor box y = 12..15 is the top four rows.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 12, 16, 4);
    glClearColor(1.f, 0.f, 0.f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    const prism::image::Image8 img = fb.readImage8();
    EXPECT_EQ(img.at(5, 0), (prism::image::Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(img.at(5, 3), (prism::image::Rgba8{255, 0, 0, 255}));
    EXPECT_EQ(img.at(5, 4), (prism::image::Rgba8{0, 0, 255, 255}));
    EXPECT_EQ(img.at(5, 15), (prism::image::Rgba8{0, 0, 255, 255}));
}

TYPED_TEST(FramebufferTest, MoveTransfersOwnership) {
    Framebuffer a(4, 4);
    const unsigned id = a.id();
    Framebuffer b = std::move(a);
    EXPECT_EQ(b.id(), id);
    EXPECT_EQ(a.id(), 0u);
    b.clear({1.f, 1.f, 1.f, 1.f});
    EXPECT_EQ(b.readImage8().at(1, 1), (prism::image::Rgba8{255, 255, 255, 255}));
}

TYPED_TEST(FramebufferTest, BadSizeIsAClearError) {
    try {
        Framebuffer fb(0, 10);
        FAIL() << "a 0x10 framebuffer was accepted";
    } catch (const prism::gl::GlError& e) {
        EXPECT_NE(std::string(e.what()).find("0x10"), std::string::npos) << e.what();
    }
}

}  // namespace
