// The speed/accuracy trade of a set of settings: which are on the Pareto front of (cost,
// error), and the cheapest within an error budget. One mechanism for every bench that
// publishes a trade (classic shading, rain, water): each gives a cost and an error per
// setting, in its own units.
//
// Usage (snippet: examples/snippets/reference_pareto.cpp):
//
//     #include "prism/reference/pareto.hpp"
//     const std::vector<double> ms = {1.0, 2.0, 3.0, 2.5}, error = {9.0, 4.0, 1.0, 5.0};
//     std::vector<std::size_t> front = prism::reference::paretoFront(ms, error);           // {0, 1, 2}
//     std::optional<std::size_t> pick = prism::reference::cheapestWithin(ms, error, 4.5);  // 1
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace prism::reference {

// Indices of the settings no other setting dominates (at most as costly and at most as
// wrong, and better in one), cheapest first. cost and error have one entry per setting.
std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error);

// The cheapest setting whose error is <= budget, among `candidates` (all when empty).
std::optional<std::size_t> cheapestWithin(std::span<const double> cost, std::span<const double> error, double budget,
                                          std::span<const std::size_t> candidates = {});

}  // namespace prism::reference
