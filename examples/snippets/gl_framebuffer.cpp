// The usage example of prism/gl/framebuffer.hpp, compiled and run by tests/snippets.
#include <cstdio>

#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/gl/framebuffer.hpp"
// [/snippet]

int main() {
    auto context = prism::gl::createContext();
    // [snippet]
    prism::gl::Framebuffer fb(256, 256);  // RGBA8 + depth24
    fb.bind();                            // binds and sets the viewport
    fb.clear({0.1f, 0.2f, 0.3f, 1.0f});   // colour and depth
    // ... draw ...
    prism::image::Image8 shot = fb.readImage8();  // top row first

    prism::gl::Framebuffer hdr(64, 64, prism::gl::ColorFormat::Rgba32F);
    prism::image::ImageF values = hdr.readImageF();  // unclamped floats
    // [/snippet]
    const prism::image::Rgba8 expected{26, 51, 76, 255};
    const prism::image::Rgba8 got = shot.at(0, 0);
    std::printf("clear colour read back: %d %d %d %d\n", got[0], got[1], got[2], got[3]);
    return got == expected && values.width == 64 ? 0 : 1;
}
