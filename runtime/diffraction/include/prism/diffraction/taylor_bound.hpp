// How many Taylor terms N the expansion of exp(i k w h) needs (diffraction thesis section 2.3.3):
// the Lagrange bound |E_N| <= e^x x^(N+1) / (N+1)!, with x = k_max w_max h_max,
// k_max = 2 pi / lambda_min, w_max = 2 and h_max the largest |h| after mean subtraction.
//
// Usage (snippet: examples/snippets/diffraction_taylor_bound.cpp):
//
//     #include "prism/diffraction/taylor_bound.hpp"
//     using namespace prism::diffraction;
//     double x = taylorArgument(/*h_max nm*/ 150, /*lambda_min nm*/ 380);  // 4.96
//     int n = termsForTolerance(150, 380, 1e-6);                           // smallest N with bound <= 1e-6
//     double e = taylorErrorBound(x, n);                                   // <= 1e-6
#pragma once

#include <stdexcept>

namespace prism::diffraction {

inline constexpr int kMaxTaylorTerms = 200;

// Thrown when the tolerance needs more than kMaxTaylorTerms terms.
struct TooManyTermsError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

double taylorArgument(double maxHeightNm, double minWavelengthNm);
// e^x x^(N+1) / (N+1)!, computed in log space (no overflow); 0 for x = 0.
double taylorErrorBound(double x, int terms);
// The smallest N in 0..kMaxTaylorTerms whose bound is <= tolerance. Throws std::invalid_argument
// for a non-positive or non-finite input and TooManyTermsError when N would exceed the limit.
int termsForTolerance(double maxHeightNm, double minWavelengthNm, double tolerance);

}  // namespace prism::diffraction
