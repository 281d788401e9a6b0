// Periodic amplitude and isolated pixels of an image (see prism/test/look_metrics.hpp).
#include "prism/test/look_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace prism::test {
namespace {

// Power of one line's DFT at `cycles` per pixel, the line's mean removed, as an amplitude^2.
double linePower(const std::vector<double>& line, double cycles) {
    double mean = 0.0;
    for (double v : line) mean += v;
    mean /= static_cast<double>(line.size());
    std::complex<double> sum = 0.0;
    for (std::size_t i = 0; i < line.size(); ++i)
        sum += (line[i] - mean) * std::polar(1.0, -2.0 * std::numbers::pi * cycles * static_cast<double>(i));
    const double amplitude = 2.0 * std::abs(sum) / static_cast<double>(line.size());
    return amplitude * amplitude;
}

// Root-mean-square amplitude over the window's rows (alongRows) or columns at one frequency.
double amplitudeAt(const image::Image8& image, PixelRect w, double cycles, bool alongRows) {
    const int lines = alongRows ? w.y1 - w.y0 : w.x1 - w.x0;
    const int length = alongRows ? w.x1 - w.x0 : w.y1 - w.y0;
    double power = 0.0;
    std::vector<double> line(static_cast<std::size_t>(length));
    for (int l = 0; l < lines; ++l) {
        for (int i = 0; i < length; ++i)
            line[static_cast<std::size_t>(i)] =
                luminance(alongRows ? image.at(w.x0 + i, w.y0 + l) : image.at(w.x0 + l, w.y0 + i));
        power += linePower(line, cycles);
    }
    return std::sqrt(power / std::max(1, lines));
}

}  // namespace

double luminance(const image::Rgba8& p) {
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

PeriodicAmplitude periodicAmplitude(const image::Image8& image, PixelRect window, double minPeriod, double maxPeriod) {
    PeriodicAmplitude best;
    // Frequencies 1/8 of a bin apart across the band, so a period between two bins is not missed.
    const int length = std::min(window.x1 - window.x0, window.y1 - window.y0);
    const double step = 0.125 / std::max(1, length);
    for (double f = 1.0 / maxPeriod; f <= 1.0 / minPeriod + 1e-12; f += step) {
        best.alongRows = std::max(best.alongRows, amplitudeAt(image, window, f, true));
        best.alongColumns = std::max(best.alongColumns, amplitudeAt(image, window, f, false));
    }
    return best;
}

std::size_t isolatedPixels(const image::Image8& image, double threshold) {
    std::size_t count = 0;
    for (int y = 1; y + 1 < image.height; ++y)
        for (int x = 1; x + 1 < image.width; ++x) {
            const double c = luminance(image.at(x, y));
            bool darker = true, brighter = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    if (dx == 0 && dy == 0) continue;
                    const double n = luminance(image.at(x + dx, y + dy));
                    darker = darker && c < n - threshold;
                    brighter = brighter && c > n + threshold;
                }
            if (darker || brighter) ++count;
        }
    return count;
}

}  // namespace prism::test
