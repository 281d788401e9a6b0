// Colour difference for measuring the diffraction shader's error: linear sRGB -> CIELAB (D65
// white) and CIEDE2000 (Sharma, Wu & Dalal 2005).
//
// Usage (snippet: examples/snippets/diffraction_colour_difference.cpp):
//
//     #include "prism/diffraction/colour_difference.hpp"
//     using namespace prism::diffraction;
//     Lab a = linearSrgbToLab({0.5, 0.2, 0.1}), b = linearSrgbToLab({0.5, 0.21, 0.1});
//     double dE = ciede2000(a, b);  // ~1 is a just-noticeable difference
#pragma once

#include "prism/diffraction/colour.hpp"

namespace prism::diffraction {

struct Lab {
    double l = 0, a = 0, b = 0;
};

// IEC 61966-2-1 linear sRGB -> XYZ -> CIELAB relative to the D65 white (0.95047, 1, 1.08883).
Lab linearSrgbToLab(LinearRgb rgb);
double ciede2000(Lab first, Lab second);

}  // namespace prism::diffraction
