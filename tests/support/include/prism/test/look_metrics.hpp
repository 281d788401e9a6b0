// Image metrics that catch what a golden at 160 px cannot: a regular pattern at one spatial
// frequency (a lattice of dots, one per grid cell) and isolated pixels much darker or
// brighter than all eight neighbours (a hole in a surface, a NaN written as black). The
// full-size look tier (tests/look) and the water thin-film test use them.
//
//     #include "prism/test/look_metrics.hpp"
//
//     prism::image::Image8 img = prism::image::readPng("render.png");
//     double a = prism::test::periodicAmplitude(img, {0, 0, img.width, img.height}, 6.0, 9.0).lattice();
//     std::size_t holes = prism::test::isolatedPixels(img, 40.0);  // 40/255 off every neighbour
#pragma once

#include <cstddef>

#include "prism/image/image.hpp"

namespace prism::test {

struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
};

// Rec. 709 luminance of a pixel, 0..255.
double luminance(const image::Rgba8& p);

struct PeriodicAmplitude {
    double alongRows = 0.0, alongColumns = 0.0;
    // A lattice (dots) is periodic along both axes; a stripe or a rain streak along one.
    double lattice() const { return alongRows < alongColumns ? alongRows : alongColumns; }
};

// The largest amplitude (luminance levels, 0..255) of a sinusoid whose period lies in
// [minPeriod, maxPeriod] pixels, along the rows and along the columns of the window: the
// DFT of each row (column) at that one frequency, |X(f)| 2 / N, averaged in power over the
// rows (columns) after removing each line's mean. A lattice of dots one cell apart puts
// its energy there in both; a smooth image has next to none.
PeriodicAmplitude periodicAmplitude(const image::Image8& image, PixelRect window, double minPeriod, double maxPeriod);

// Pixels whose luminance differs by more than `threshold` levels from every one of its eight
// neighbours, in the same direction (all darker or all brighter): a dot one pixel wide.
std::size_t isolatedPixels(const image::Image8& image, double threshold);

}  // namespace prism::test
