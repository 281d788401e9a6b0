// KissFFT spectra of height fields and their Gaussian-windowed evaluation (see spectrum.hpp).
#include "prism/diffraction/spectrum.hpp"

#include <kissfft.hh>

#include <cmath>
#include <numbers>
#include <vector>
#include <stdexcept>

namespace prism::diffraction {
namespace {

using Complex = std::complex<double>;

// Index of frequency j in an FFT of size n, or -1 when |j| is beyond what n samples resolve.
int fftIndex(int j, int n) {
    const int lowest = -((n - 1) / 2);
    const int highest = n / 2;
    if (j < lowest || j > highest) return -1;
    return j < 0 ? j + n : j;
}

}  // namespace

GaussianWindow defaultWindow(const HeightField& field) {
    return {0.25 * field.widthNm(), 4.0};
}

Complex Spectrum::coefficient(int jx, int jy) const {
    const int ix = fftIndex(jx, width), iy = fftIndex(jy, height);
    if (ix < 0 || iy < 0) return {0.0, 0.0};
    return coefficients[static_cast<std::size_t>(iy) * width + ix];
}

Complex Spectrum::evaluate(double fx, double fy, const GaussianWindow& window) const {
    // sigma_f in cycles per nm; in units of frequency bins it is L * sigma_f.
    const double sigmaF = 1.0 / (2.0 * std::numbers::pi * window.sigmaNm);
    const double reach = window.radiusSigmas * sigmaF;
    const double bx = fx * periodXNm, by = fy * periodYNm;  // frequency in bins
    const int x0 = static_cast<int>(std::ceil((fx - reach) * periodXNm));
    const int x1 = static_cast<int>(std::floor((fx + reach) * periodXNm));
    const int y0 = static_cast<int>(std::ceil((fy - reach) * periodYNm));
    const int y1 = static_cast<int>(std::floor((fy + reach) * periodYNm));
    const double inv2s2 = 1.0 / (2.0 * sigmaF * sigmaF);
    if (x1 < x0 || y1 < y0) return {0.0, 0.0};
    // The Gaussian is separable, exp(-(dx^2 + dy^2) k) = exp(-dx^2 k) exp(-dy^2 k): one exp per
    // column and per row instead of one per coefficient.
    thread_local std::vector<double> columnWeight;
    columnWeight.resize(static_cast<std::size_t>(x1 - x0 + 1));
    for (int jx = x0; jx <= x1; ++jx) {
        const double dx = (jx - bx) / periodXNm;
        columnWeight[static_cast<std::size_t>(jx - x0)] = std::exp(-dx * dx * inv2s2);
    }
    Complex sum{0.0, 0.0};
    for (int jy = y0; jy <= y1; ++jy) {
        const double dy = (jy - by) / periodYNm;
        const double rowWeight = std::exp(-dy * dy * inv2s2);
        for (int jx = x0; jx <= x1; ++jx) {
            const double dx = (jx - bx) / periodXNm;
            if (dx * dx + dy * dy > reach * reach) continue;
            const Complex c = coefficient(jx, jy);
            if (c != Complex{0.0, 0.0}) sum += c * (rowWeight * columnWeight[static_cast<std::size_t>(jx - x0)]);
        }
    }
    return sum;
}

Spectrum fourierSeries(const std::vector<Complex>& samples, int width, int height, double pixelNm) {
    if (width < 1 || height < 1 || samples.size() != static_cast<std::size_t>(width) * height) {
        throw std::invalid_argument("fourierSeries: samples do not match width x height");
    }
    Spectrum s;
    s.width = width;
    s.height = height;
    s.periodXNm = width * pixelNm;
    s.periodYNm = height * pixelNm;
    s.coefficients.resize(samples.size());
    const kissfft<double> rowFft(static_cast<std::size_t>(width), false);
    for (int y = 0; y < height; ++y) {
        rowFft.transform(&samples[static_cast<std::size_t>(y) * width],
                         &s.coefficients[static_cast<std::size_t>(y) * width]);
    }
    if (height > 1) {
        const kissfft<double> columnFft(static_cast<std::size_t>(height), false);
        std::vector<Complex> in(static_cast<std::size_t>(height)), out(static_cast<std::size_t>(height));
        for (int x = 0; x < width; ++x) {
            for (int y = 0; y < height; ++y) in[y] = s.coefficients[static_cast<std::size_t>(y) * width + x];
            columnFft.transform(in.data(), out.data());
            for (int y = 0; y < height; ++y) s.coefficients[static_cast<std::size_t>(y) * width + x] = out[y];
        }
    }
    const double scale = 1.0 / static_cast<double>(samples.size());
    for (Complex& c : s.coefficients) c *= scale;
    return s;
}

TaylorSpectra taylorSpectra(const HeightField& field, int terms) {
    if (terms < 0 || terms > 200) throw std::invalid_argument("Taylor terms must be in 0..200");
    TaylorSpectra t;
    std::vector<Complex> power(field.heightsNm.size(), Complex{1.0, 0.0});  // h^0
    for (int n = 0; n <= terms; ++n) {
        t.terms.push_back(fourierSeries(power, field.width, field.height, field.pixelNm));
        for (std::size_t i = 0; i < power.size(); ++i) power[i] *= field.heightsNm[i];
    }
    return t;
}

Complex TaylorSpectra::evaluate(double fx, double fy, double k, double w, const GaussianWindow& window) const {
    // (i k w)^n / n!, built up term by term.
    Complex factor{1.0, 0.0};
    Complex sum{0.0, 0.0};
    for (int n = 0; n <= termCount(); ++n) {
        if (n > 0) factor *= Complex{0.0, k * w / n};
        sum += factor * terms[n].evaluate(fx, fy, window);
    }
    return sum;
}

Spectrum exactSpectrum(const HeightField& field, double phasePerNm) {
    std::vector<Complex> p(field.heightsNm.size());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::polar(1.0, phasePerNm * field.heightsNm[i]);
    return fourierSeries(p, field.width, field.height, field.pixelNm);
}

}  // namespace prism::diffraction
