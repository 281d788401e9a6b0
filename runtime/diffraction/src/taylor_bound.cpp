// The thesis's Taylor error bound and the term count it implies (see taylor_bound.hpp).
#include "prism/diffraction/taylor_bound.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace prism::diffraction {

double taylorArgument(double maxHeightNm, double minWavelengthNm) {
    return 2.0 * std::numbers::pi / minWavelengthNm * 2.0 * maxHeightNm;
}

double taylorErrorBound(double x, int terms) {
    if (x <= 0.0) return 0.0;
    return std::exp(x + (terms + 1) * std::log(x) - std::lgamma(terms + 2.0));
}

int termsForTolerance(double maxHeightNm, double minWavelengthNm, double tolerance) {
    if (!(std::isfinite(maxHeightNm) && maxHeightNm >= 0.0)) {
        throw std::invalid_argument("maximum height must be a finite number >= 0 nm");
    }
    if (!(std::isfinite(minWavelengthNm) && minWavelengthNm > 0.0)) {
        throw std::invalid_argument("wavelength must be a finite number > 0 nm");
    }
    if (!(std::isfinite(tolerance) && tolerance > 0.0 && tolerance < 1.0)) {
        throw std::invalid_argument("tolerance must be in (0, 1)");
    }
    const double x = taylorArgument(maxHeightNm, minWavelengthNm);
    for (int n = 0; n <= kMaxTaylorTerms; ++n) {
        if (taylorErrorBound(x, n) <= tolerance) return n;
    }
    char message[256];
    std::snprintf(message, sizeof message,
                  "a height of %g nm at %g nm needs more than %d Taylor terms for tolerance %g; lower the height "
                  "(subtract the mean) or use the exact path",
                  maxHeightNm, minWavelengthNm, kMaxTaylorTerms, tolerance);
    throw TooManyTermsError(message);
}

}  // namespace prism::diffraction
