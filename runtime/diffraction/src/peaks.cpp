// Peak finding in the plane of incidence (see peaks.hpp).
#include "prism/diffraction/peaks.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace prism::diffraction {

std::vector<Peak> findPeaks(const StamBrdf& brdf, const PeakSearch& search) {
    if (!(search.incidenceDeg >= 0.0 && search.incidenceDeg <= 89.9)) {
        throw std::invalid_argument("incidence must be in 0..89.9 degrees");
    }
    if (!(search.stepDeg > 0.0 && search.stepDeg <= 1.0)) throw std::invalid_argument("step must be in (0, 1] degrees");
    const Direction toLight = fromAngles(search.incidenceDeg, 180.0);  // light on the -x side
    const auto value = [&](double thetaDeg, double lambda) {
        return brdf.spectral(toLight, fromAngles(thetaDeg, 0.0), lambda);  // theta < 0 flips to -x
    };
    const double sinIncidence = std::sin(search.incidenceDeg * std::numbers::pi / 180.0);
    std::vector<Peak> all;
    const int count = static_cast<int>(std::floor(2.0 * search.maxAngleDeg / search.stepDeg)) + 1;
    for (double lambda : search.wavelengthsNm) {
        std::vector<double> samples(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) samples[i] = value(-search.maxAngleDeg + i * search.stepDeg, lambda);
        const double strongest = *std::max_element(samples.begin(), samples.end());
        std::vector<Peak> peaks;
        for (int i = 1; i + 1 < count; ++i) {
            if (!(samples[i] > samples[i - 1] && samples[i] >= samples[i + 1])) continue;
            if (samples[i] < search.minRelativeIntensity * strongest) continue;
            // Golden-section search on the bracketing interval.
            double a = -search.maxAngleDeg + (i - 1) * search.stepDeg, b = a + 2.0 * search.stepDeg;
            const double g = (std::sqrt(5.0) - 1.0) / 2.0;
            double c = b - g * (b - a), d = a + g * (b - a);
            double fc = value(c, lambda), fd = value(d, lambda);
            while (b - a > 1e-5) {
                if (fc > fd) {
                    b = d, d = c, fd = fc, c = b - g * (b - a), fc = value(c, lambda);
                } else {
                    a = c, c = d, fc = fd, d = a + g * (b - a), fd = value(d, lambda);
                }
            }
            const double theta = 0.5 * (a + b);
            const double s = std::sin(theta * std::numbers::pi / 180.0);
            const int order = static_cast<int>(std::lround((s - sinIncidence) * search.periodNm / lambda));
            peaks.push_back({lambda, order, theta, value(theta, lambda)});
        }
        double reference = 0.0;
        for (const Peak& p : peaks) {
            if (p.order == 0) reference = std::max(reference, p.relativeIntensity);
        }
        if (reference == 0.0) reference = strongest;
        for (Peak& p : peaks) p.relativeIntensity /= reference;
        all.insert(all.end(), peaks.begin(), peaks.end());
    }
    return all;
}

}  // namespace prism::diffraction
