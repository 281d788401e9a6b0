// The Taylor error bound against the diffraction thesis's own numbers (section 2.3.3) and the
// term counts and errors it implies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "prism/diffraction/taylor_bound.hpp"

using namespace prism::diffraction;

TEST(DiffractionTaylorBound, MatchesTheThesisTable) {
    const double x = 1.5 * std::numbers::pi;  // the thesis's x_max
    EXPECT_NEAR(taylorErrorBound(x, 20) / 2.9950e-4, 1.0, 2e-3);
    EXPECT_NEAR(taylorErrorBound(x, 25) / 8.8150e-8, 1.0, 2e-3);
    EXPECT_NEAR(taylorErrorBound(x, 30) / 1.0050e-11, 1.0, 2e-3);
}

TEST(DiffractionTaylorBound, TermsAreTheSmallestMeetingTheTolerance) {
    const int n = termsForTolerance(150.0, 380.0, 1e-6);
    const double x = taylorArgument(150.0, 380.0);
    EXPECT_LE(taylorErrorBound(x, n), 1e-6);
    EXPECT_GT(taylorErrorBound(x, n - 1), 1e-6);
}

TEST(DiffractionTaylorBound, MoreHeightOrTighterToleranceNeedsMoreTerms) {
    EXPECT_LT(termsForTolerance(50.0, 380.0, 1e-6), termsForTolerance(150.0, 380.0, 1e-6));
    EXPECT_LT(termsForTolerance(150.0, 380.0, 1e-3), termsForTolerance(150.0, 380.0, 1e-9));
    EXPECT_LT(termsForTolerance(150.0, 700.0, 1e-6), termsForTolerance(150.0, 380.0, 1e-6));
}

TEST(DiffractionTaylorBound, ZeroHeightNeedsNoTerms) {
    EXPECT_EQ(termsForTolerance(0.0, 380.0, 1e-9), 0);
}

TEST(DiffractionTaylorBound, HugeHeightIsAClearError) {
    EXPECT_THROW(termsForTolerance(5000.0, 380.0, 1e-6), TooManyTermsError);
    EXPECT_THROW(termsForTolerance(1e300, 380.0, 1e-6), TooManyTermsError);
    EXPECT_NO_THROW(termsForTolerance(1000.0, 380.0, 1e-6));  // x = 33, N < 200
}

TEST(DiffractionTaylorBound, BadInputIsAnError) {
    EXPECT_THROW(termsForTolerance(-1.0, 380.0, 1e-6), std::invalid_argument);
    EXPECT_THROW(termsForTolerance(150.0, 0.0, 1e-6), std::invalid_argument);
    EXPECT_THROW(termsForTolerance(150.0, 380.0, 0.0), std::invalid_argument);
    EXPECT_THROW(termsForTolerance(NAN, 380.0, 1e-6), std::invalid_argument);
}
