// The usage example of prism/diffraction/taylor_bound.hpp, compiled and run by tests/snippets.
#include <cmath>
// [snippet]
#include "prism/diffraction/taylor_bound.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    // [snippet]
    double x = taylorArgument(/*h_max nm*/ 150, /*lambda_min nm*/ 380);  // 4.96
    int n = termsForTolerance(150, 380, 1e-6);                           // smallest N with bound <= 1e-6
    double e = taylorErrorBound(x, n);                                   // <= 1e-6
    // [/snippet]
    const bool smallest = n > 0 && taylorErrorBound(x, n - 1) > 1e-6;
    return std::abs(x - 4.96) < 0.005 && e <= 1e-6 && smallest ? 0 : 1;
}
