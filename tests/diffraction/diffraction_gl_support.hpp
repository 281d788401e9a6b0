// Shared by the diffraction GL tests: the test grating (2500 nm period, 60 nm amplitude).
#pragma once

#include "prism/diffraction/diffraction_gl.hpp"

namespace prism::diffraction::test {

inline const StamBrdf& testGrating() {
    static const StamBrdf brdf(sinusoidGrating({.periodNm = 2500.0, .amplitudeNm = 60.0, .periods = 8}),
                               {.tolerance = 1e-5, .window = GaussianWindow{1000.0, 4.0}});
    return brdf;
}

}  // namespace prism::diffraction::test
