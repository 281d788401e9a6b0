// Fourier spectra of a height-field patch (KissFFT, double precision) and their evaluation at a
// continuous spatial frequency through a Gaussian window (diffraction thesis section 2.3.4).
//
// The patch is one tile of a periodic surface, so p(x, y) = exp(i k w h) has Fourier-series
// coefficients c_j = DFT(p)[j] / samples at the frequencies j / L (cycles per nm). Windowing
// the infinite surface with a Gaussian of standard deviation sigmaNm turns each line into a
// Gaussian of sigma_f = 1 / (2 pi sigmaNm):  P(f) = sum_j c_j exp(-|f - j/L|^2 / (2 sigma_f^2)),
// truncated at radiusSigmas * sigma_f. A flat mirror has P(0) = 1.
//
// Usage (snippet: examples/snippets/diffraction_spectrum.cpp):
//
//     #include "prism/diffraction/spectrum.hpp"
//     using namespace prism::diffraction;
//     HeightField g = sinusoidGrating({.periodNm = 2500, .amplitudeNm = 150});
//     subtractMean(g);
//     TaylorSpectra taylor = taylorSpectra(g, /*terms N*/ 25);  // FFTs of h^0..h^N
//     GaussianWindow window = defaultWindow(g);
//     std::complex<double> p = taylor.evaluate(1.0 / 2500, 0.0, /*k*/ 2 * 3.14159265 / 550, /*w*/ 2.0, window);
//     Spectrum exact = exactSpectrum(g, 2 * 3.14159265 / 550 * 2.0);     // no Taylor series
//     std::complex<double> q = exact.evaluate(1.0 / 2500, 0.0, window);  // ~ p
#pragma once

#include <complex>
#include <vector>

#include "prism/diffraction/height_field.hpp"

namespace prism::diffraction {

struct GaussianWindow {
    double sigmaNm = 16000.0;   // spatial standard deviation (coherence length)
    double radiusSigmas = 4.0;  // truncation of the frequency-domain Gaussian
};
// sigma = a quarter of the patch width: the patch spans 4 sigma (the thesis's choice).
GaussianWindow defaultWindow(const HeightField& field);

// Fourier-series coefficients of one sampled periodic function on the patch grid.
struct Spectrum {
    int width = 0, height = 0;
    double periodXNm = 1.0, periodYNm = 1.0;         // the patch size L
    std::vector<std::complex<double>> coefficients;  // DFT / (width * height), FFT order

    // c_j for integer frequency indices (jx, jy); zero outside the band the grid resolves.
    std::complex<double> coefficient(int jx, int jy) const;
    // The windowed spectrum at (fx, fy) in cycles per nm.
    std::complex<double> evaluate(double fx, double fy, const GaussianWindow& window) const;
};

// Forward 2D FFT (KissFFT, double) of width x height complex samples, divided by their count.
Spectrum fourierSeries(const std::vector<std::complex<double>>& samples, int width, int height, double pixelNm);

// The FFTs of h^0 .. h^N (the thesis's precomputation, Algorithm 3.1) of a height field.
struct TaylorSpectra {
    std::vector<Spectrum> terms;                                          // terms[n] = fourierSeries(h^n)
    int termCount() const { return static_cast<int>(terms.size()) - 1; }  // N
    // P(f) = sum_{n<=N} (i k w)^n / n! * H_n(f), windowed.
    std::complex<double> evaluate(double fx, double fy, double k, double w, const GaussianWindow& window) const;
};
TaylorSpectra taylorSpectra(const HeightField& field, int terms);

// The exact path: fourierSeries(exp(i * phasePerNm * h)), phasePerNm = k * w.
Spectrum exactSpectrum(const HeightField& field, double phasePerNm);

}  // namespace prism::diffraction
