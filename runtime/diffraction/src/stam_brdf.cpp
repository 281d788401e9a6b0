// Stam's BRDF on the Taylor and exact paths (see stam_brdf.hpp).
#include "prism/diffraction/stam_brdf.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "prism/diffraction/taylor_bound.hpp"

namespace prism::diffraction {
namespace {

constexpr double kHorizonCos = 1e-6;

void checkDirection(const Direction& d, const char* name) {
    const double len2 = d.x * d.x + d.y * d.y + d.z * d.z;
    if (!std::isfinite(len2) || std::abs(len2 - 1.0) > 1e-6) {
        throw std::invalid_argument(std::string(name) + " must be a finite unit vector");
    }
}

}  // namespace

Direction fromAngles(double thetaDeg, double phiDeg) {
    const double t = thetaDeg * std::numbers::pi / 180.0, p = phiDeg * std::numbers::pi / 180.0;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

StamGeometry stamGeometry(Direction wi, Direction wr) {
    checkDirection(wi, "light direction");
    checkDirection(wr, "view direction");
    StamGeometry g;
    g.u = -wi.x - wr.x;
    g.v = -wi.y - wr.y;
    g.w = -wi.z - wr.z;
    if (wi.z <= kHorizonCos || wr.z <= kHorizonCos) return g;  // factor 0
    const double oneDot = 1.0 + wi.x * wr.x + wi.y * wr.y + wi.z * wr.z;
    const double ratio = oneDot / g.w;  // |w| >= 2e-6 here
    g.factor = ratio * ratio / (wi.z * wr.z);
    return g;
}

StamBrdf::StamBrdf(HeightField field, const Options& options) : field_(std::move(field)), path_(options.path) {
    if (field_.width < 1 || field_.height < 1 ||
        field_.heightsNm.size() != static_cast<std::size_t>(field_.width) * field_.height) {
        throw std::invalid_argument("height field is empty or its size does not match its samples");
    }
    subtractMean(field_);
    window_ = options.window ? *options.window : defaultWindow(field_);
    if (!(window_.sigmaNm > 0.0) || !(window_.radiusSigmas > 0.0)) {
        throw std::invalid_argument("Gaussian window sigma and radius must be > 0");
    }
    if (options.terms) {
        if (*options.terms < 0 || *options.terms > kMaxTaylorTerms) {
            throw TooManyTermsError("Taylor terms must be in 0.." + std::to_string(kMaxTaylorTerms));
        }
        terms_ = *options.terms;
    } else if (path_ == Path::Taylor) {
        terms_ = termsForTolerance(maxAbsHeight(field_), kLambdaMinNm, options.tolerance);
    }
    if (path_ == Path::Taylor) taylor_ = taylorSpectra(field_, terms_);
}

std::complex<double> StamBrdf::spectrumAt(const StamGeometry& g, double lambda) const {
    const double k = 2.0 * std::numbers::pi / lambda;
    const double fx = g.u / lambda, fy = g.v / lambda;
    if (path_ == Path::Taylor) return taylor_.evaluate(fx, fy, k, g.w, window_);
    return exactSpectrum(field_, k * g.w).evaluate(fx, fy, window_);
}

double StamBrdf::spectral(Direction wi, Direction wr, double lambda) const {
    if (!(std::isfinite(lambda) && lambda > 0.0)) throw std::invalid_argument("wavelength must be > 0 nm");
    const StamGeometry g = stamGeometry(wi, wr);
    if (g.factor == 0.0) return 0.0;
    return g.factor * std::norm(spectrumAt(g, lambda));
}

Xyz StamBrdf::xyz(Direction wi, Direction wr, const std::vector<SpectralWeight>& weights) const {
    const StamGeometry g = stamGeometry(wi, wr);
    Xyz sum;
    if (g.factor == 0.0) return sum;
    for (const SpectralWeight& s : weights) sum = sum + (g.factor * std::norm(spectrumAt(g, s.wavelengthNm))) * s.xyz;
    return sum;
}

}  // namespace prism::diffraction
