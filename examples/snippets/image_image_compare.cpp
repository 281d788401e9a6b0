// The usage example of prism/image/image_compare.hpp, compiled and run by tests/snippets.
// [snippet]
#include <iostream>

#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
// [/snippet]

int main() {
    const prism::image::Image8 golden(32, 32, {10, 20, 30, 255});
    prism::image::Image8 actual = golden;
    actual.set(5, 5, {200, 20, 30, 255});  // two pixels far off: 2 of 1024 is over 0.1 %
    actual.set(6, 5, {200, 20, 30, 255});
    // [snippet]
    prism::image::ImageComparison cmp = prism::image::compareImages(actual, golden);
    prism::image::Thresholds t{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};
    if (!prism::image::passes(cmp, t)) {
        std::cerr << prism::image::describe(cmp, t) << "\n";
        prism::image::writePng("out/phong.diff.png", cmp.diff);
    }
    // [/snippet]
    return !prism::image::passes(cmp, t) && cmp.pixelsOver == 2 ? 0 : 1;
}
