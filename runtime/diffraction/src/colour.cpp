// Colour matching functions, D65, wavelength grids and XYZ -> sRGB (see colour.hpp).
#include "prism/diffraction/colour.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cie_tables.hpp"

namespace prism::diffraction {
namespace {

double sampleLinear(const double* values, int count, double startNm, double stepNm, double wavelengthNm) {
    const double position = (wavelengthNm - startNm) / stepNm;
    if (!(position >= 0.0) || position > count - 1) return 0.0;
    const int i = std::min(static_cast<int>(position), count - 2);
    const double t = position - i;
    return values[i] * (1.0 - t) + values[i + 1] * t;
}

}  // namespace

Xyz colourMatching(double wavelengthNm) {
    const detail::CieSourceTables& t = detail::cieSourceTables();
    return {sampleLinear(t.x, t.cmfCount, t.cmfStartNm, t.cmfStepNm, wavelengthNm),
            sampleLinear(t.y, t.cmfCount, t.cmfStartNm, t.cmfStepNm, wavelengthNm),
            sampleLinear(t.z, t.cmfCount, t.cmfStartNm, t.cmfStepNm, wavelengthNm)};
}

double d65(double wavelengthNm) {
    const detail::CieSourceTables& t = detail::cieSourceTables();
    return sampleLinear(t.d65, t.d65Count, t.d65StartNm, t.d65StepNm, wavelengthNm);
}

std::string cmfSource() {
    return detail::cieSourceTables().cmfSource;
}
std::string d65Source() {
    return detail::cieSourceTables().d65Source;
}

bool isSupportedWavelengthStep(int stepNm) {
    return stepNm == 1 || stepNm == 2 || stepNm == 5 || stepNm == 10 || stepNm == 20;
}

std::vector<SpectralWeight> spectralWeights(int stepNm) {
    if (!isSupportedWavelengthStep(stepNm)) {
        throw std::invalid_argument("wavelength step " + std::to_string(stepNm) +
                                    " nm is not supported; use 1, 2, 5, 10 or 20 nm");
    }
    // Each 5 nm table sample carries the mass D65 * cmf * 5 nm. Spread it onto the grid with a
    // tent of half-width h = max(step, 5 nm) scaled by step / h: coarse grids collect whole
    // masses (nothing is skipped), fine grids interpolate the product linearly. Either way the
    // grid's sum matches the 5 nm table's, so white stays white at every step.
    const detail::CieSourceTables& t = detail::cieSourceTables();
    const double h = std::max(static_cast<double>(stepNm), t.cmfStepNm);
    std::vector<SpectralWeight> grid;
    const int count = static_cast<int>((kLambdaMaxNm - kLambdaMinNm) / stepNm) + 1;
    for (int j = 0; j < count; ++j) grid.push_back({kLambdaMinNm + j * stepNm, Xyz{}});
    double ySum = 0.0;
    for (int i = 0; i < t.cmfCount; ++i) {
        const double lambda = t.cmfStartNm + i * t.cmfStepNm;
        if (lambda < kLambdaMinNm || lambda > kLambdaMaxNm) continue;
        const Xyz mass = (d65(lambda) * t.cmfStepNm) * Xyz{t.x[i], t.y[i], t.z[i]};
        for (SpectralWeight& s : grid) {
            const double tent = 1.0 - std::abs(s.wavelengthNm - lambda) / h;
            if (tent > 0.0) s.xyz = s.xyz + (tent * stepNm / h) * mass;
        }
    }
    for (const SpectralWeight& s : grid) ySum += s.xyz.y;
    for (SpectralWeight& s : grid) s.xyz = (1.0 / ySum) * s.xyz;
    return grid;
}

LinearRgb xyzToLinearSrgb(Xyz c) {
    // IEC 61966-2-1:1999, section 5.2 (the inverse of its RGB -> XYZ matrix, 4 decimals).
    return {3.2406 * c.x - 1.5372 * c.y - 0.4986 * c.z,   //
            -0.9689 * c.x + 1.8758 * c.y + 0.0415 * c.z,  //
            0.0557 * c.x - 0.2040 * c.y + 1.0570 * c.z};
}

double srgbEncode(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

}  // namespace prism::diffraction
