// The usage example of prism/image/image.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/image/image.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::image::Image8 img(64, 32, {255, 0, 0, 255});  // 64x32, opaque red
    img.set(3, 4, {0, 0, 255, 255});                     // x = 3, y = 4 (4th row from the top)
    prism::image::Rgba8 p = img.at(3, 4);
    std::uint8_t* raw = img.data.data();  // width*height*4 bytes, row-major

    prism::image::ImageF hdr(8, 8);  // float RGBA, zero-filled
    hdr.set(0, 0, {1.5f, 0.f, 0.f, 1.f});
    std::size_t bad = prism::image::countNonFinite(hdr);     // pixels holding NaN or infinity
    prism::image::Image8 ldr = prism::image::toImage8(hdr);  // clamped to [0,1], NaN -> 0
    // [/snippet]
    hdr.set(1, 0, {NAN, 0.f, 0.f, 1.f});
    return p[2] == 255 && raw[(4 * 64 + 3) * 4 + 2] == 255 && bad == 0 && ldr.at(0, 0)[0] == 255 &&
                   prism::image::countNonFinite(hdr) == 1
               ? 0
               : 1;
}
