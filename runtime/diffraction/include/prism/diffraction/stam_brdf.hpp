// Stam's diffraction BRDF (1999) for a height field, relative to a flat mirror's specular peak at
// normal incidence (diffraction thesis section 2.3.2), per wavelength and integrated to XYZ:
//   rho_lambda = G / w^2 * |P(u / lambda, v / lambda)|^2,  G = (1 + wi.wr)^2 / (cos ti cos tr),
//   (u, v, w) = -wi - wr, P the windowed spectrum of exp(i k w h) (spectrum.hpp), F = 1.
// wi points to the light, wr to the viewer, z is the surface normal. Below the horizon
// (cos <= 1e-6) the BRDF is 0. A mirror (h = 0) at normal incidence gives rho = 1.
//
// Usage (snippet: examples/snippets/diffraction_stam_brdf.cpp):
//
//     #include "prism/diffraction/stam_brdf.hpp"
//     using namespace prism::diffraction;
//     StamBrdf brdf(sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150}), StamBrdf::Options{});
//     double r = brdf.spectral(fromAngles(0, 0), fromAngles(12.709, 0), 550);  // first order
//     Xyz c = brdf.xyz(fromAngles(0, 0), fromAngles(12.709, 0), spectralWeights(5));
#pragma once

#include <complex>
#include <optional>
#include <vector>

#include "prism/diffraction/colour.hpp"
#include "prism/diffraction/height_field.hpp"
#include "prism/diffraction/spectrum.hpp"

namespace prism::diffraction {

struct Direction {
    double x = 0, y = 0, z = 1;
};
// (sin t cos p, sin t sin p, cos t) for t, p in degrees.
Direction fromAngles(double thetaDeg, double phiDeg);

struct StamGeometry {
    double u = 0, v = 0, w = 0;  // -wi - wr
    double factor = 0;           // G / w^2, 0 below the horizon
};
// Throws std::invalid_argument for non-finite or non-unit directions.
StamGeometry stamGeometry(Direction toLight, Direction toViewer);

class StamBrdf {
  public:
    enum class Path { Taylor, Exact };
    struct Options {
        Path path = Path::Taylor;
        std::optional<int> terms{};              // N; when empty, from tolerance and the height range (Taylor path)
        double tolerance = 1e-6;                 // for the error bound (taylor_bound.hpp)
        std::optional<GaussianWindow> window{};  // default: defaultWindow(field)
    };
    // Subtracts the field's mean, picks N and precomputes the FFTs of h^n (Taylor path).
    // Throws TooManyTermsError when the heights need more than 200 terms (Taylor path).
    StamBrdf(HeightField field, const Options& options);

    double spectral(Direction toLight, Direction toViewer, double wavelengthNm) const;
    Xyz xyz(Direction toLight, Direction toViewer, const std::vector<SpectralWeight>& weights) const;

    int terms() const { return terms_; }
    Path path() const { return path_; }
    const HeightField& field() const { return field_; }
    const GaussianWindow& window() const { return window_; }
    const TaylorSpectra& taylor() const { return taylor_; }

  private:
    std::complex<double> spectrumAt(const StamGeometry& g, double wavelengthNm) const;
    HeightField field_;
    Path path_;
    int terms_ = 0;
    GaussianWindow window_;
    TaylorSpectra taylor_;
};

}  // namespace prism::diffraction
