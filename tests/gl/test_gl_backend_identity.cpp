// EGL and OSMesa both run Mesa's llvmpipe: the same program and triangle must give
// byte-identical pixels (the premise of the golden-image tests).
#include "gl_test_support.hpp"
#include "prism/image/image_compare.hpp"

namespace {

using prism::gl::Backend;

// Interpolated vertex colours plus per-pixel trigonometry, so rasterisation,
// interpolation and float maths are all compared.
prism::gl::ProgramSources shadedTriangleSources() {
    prism::gl::ProgramSources s;
    s.label = "shaded";
    s.stages.push_back({prism::catalog::Stage::Vertex,
                        "#version 330 core\n"
                        "in vec2 a_position;\nin vec4 a_color;\nout vec4 v_color;\n"
                        "void main() { v_color = a_color; gl_Position = vec4(a_position, 0.0, 1.0); }\n",
                        {{0, "shaded.vert"}}});
    s.stages.push_back({prism::catalog::Stage::Fragment,
                        "#version 330 core\n"
                        "in vec4 v_color;\nuniform float u_frequency;\nout vec4 fragColor;\n"
                        "void main() {\n"
                        "  float wave = 0.5 + 0.5 * sin(gl_FragCoord.x * u_frequency) * cos(gl_FragCoord.y * 0.31);\n"
                        "  fragColor = vec4(v_color.rgb * wave, 1.0);\n"
                        "}\n",
                        {{0, "shaded.frag"}}});
    for (const auto& a : prism::test::kContractAttributes) s.attributes.push_back({std::string(a.name), a.location});
    return s;
}

prism::image::Image8 render(prism::gl::Context& ctx) {
    ctx.makeCurrent();
    prism::gl::Program program(shadedTriangleSources());
    program.set("u_frequency", 0.23f);
    prism::gl::Framebuffer fb(96, 80);
    prism::test::drawTriangle(fb, program);
    return fb.readImage8();
}

TEST(BackendIdentity, EglAndOsMesaRenderIdenticalPixels) {
    auto egl = prism::gl::createContext(Backend::Egl);
    auto osmesa = prism::gl::createContext(Backend::OsMesa);
    const prism::image::Image8 a = render(*egl);
    const prism::image::Image8 b = render(*osmesa);

    // The image must show the triangle (not just the clear colour) to mean anything.
    std::size_t lit = 0;
    for (std::size_t i = 0; i < a.data.size(); i += 4) lit += (a.data[i] | a.data[i + 1] | a.data[i + 2]) != 0;
    EXPECT_GT(lit, a.pixelCount() / 16);  // the triangle covers 1/8 of the image

    const auto cmp = prism::image::compareImages(a, b, 0);
    EXPECT_TRUE(cmp.sizeMatches);
    EXPECT_EQ(cmp.maxChannelDiff, 0) << prism::image::describe(cmp, prism::image::Thresholds{0, 0.0, 0.0});
    EXPECT_EQ(a, b);
}

}  // namespace
