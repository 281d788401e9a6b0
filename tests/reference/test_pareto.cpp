// The Pareto front of (cost, error) and the cheapest setting within a budget, on hand-made
// settings whose front is known: dominated settings, ties in cost and in error, one setting.
#include <gtest/gtest.h>

#include <vector>

#include "prism/reference/pareto.hpp"

namespace prism::reference {
namespace {

TEST(Pareto, KeepsExactlyTheSettingsNoOtherDominates) {
    // 3 is dominated by 1 (dearer and more wrong); 4 costs as much as 2 but is more wrong;
    // 5 is as wrong as 0 but dearer; 6 is the most accurate and the dearest.
    const std::vector<double> cost = {1.0, 2.0, 3.0, 2.5, 3.0, 4.0, 9.0};
    const std::vector<double> error = {9.0, 4.0, 1.0, 5.0, 2.0, 9.0, 0.5};
    EXPECT_EQ(paretoFront(cost, error), (std::vector<std::size_t>{0, 1, 2, 6}));
}

TEST(Pareto, OfSettingsThatCostTheSameOnlyTheLeastWrongIsOnTheFront) {
    // Listed more wrong first, so a sort by cost alone would keep both.
    const std::vector<double> cost = {3.0, 3.0, 1.0}, error = {2.0, 1.0, 5.0};
    EXPECT_EQ(paretoFront(cost, error), (std::vector<std::size_t>{2, 1}));
    EXPECT_EQ(cheapestWithin(cost, std::vector<double>{1.0, 1.0, 5.0}, 2.0), 0u);  // a tie: the first
}

TEST(Pareto, OneSettingIsItsOwnFrontAndMismatchedSizesAreAnError) {
    EXPECT_EQ(paretoFront(std::vector<double>{5.0}, std::vector<double>{3.0}), (std::vector<std::size_t>{0}));
    EXPECT_TRUE(paretoFront(std::vector<double>{}, std::vector<double>{}).empty());
    EXPECT_THROW(paretoFront(std::vector<double>{1.0, 2.0}, std::vector<double>{1.0}), std::invalid_argument);
}

TEST(Pareto, CheapestWithinABudgetAmongAllOrTheCandidates) {
    const std::vector<double> cost = {1.0, 2.0, 3.0, 2.5};
    const std::vector<double> error = {9.0, 4.0, 1.0, 5.0};
    EXPECT_EQ(cheapestWithin(cost, error, 4.0), 1u);
    EXPECT_EQ(cheapestWithin(cost, error, 1.0), 2u);
    EXPECT_EQ(cheapestWithin(cost, error, 0.5), std::nullopt);
    const std::vector<std::size_t> candidates = {2, 3};
    EXPECT_EQ(cheapestWithin(cost, error, 6.0, candidates), 3u);
}

}  // namespace
}  // namespace prism::reference
