// The usage example of prism/image/png_io.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/image/png_io.hpp"
// [/snippet]

int main() {
    const prism::image::Image8 image(16, 8, {0, 128, 255, 255});
    prism::image::writePng("tests/golden/phong.png", image);
    // [snippet]
    prism::image::writePng("out/phong.png", image);  // atomic: temp file + rename
    prism::image::Image8 golden = prism::image::readPng("tests/golden/phong.png");
    // [/snippet]
    return golden == image && prism::image::readPng("out/phong.png") == image ? 0 : 1;
}
