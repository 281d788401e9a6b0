// The Pareto front of (cost, error) and the cheapest setting within a budget (pareto.hpp).
#include "prism/reference/pareto.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace prism::reference {

std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error) {
    if (cost.size() != error.size()) throw std::invalid_argument("paretoFront: one cost and one error per setting");
    std::vector<std::size_t> order(cost.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Cheapest first, the less wrong first among equal costs: a setting is on the front when
    // it is less wrong than every cheaper one.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (cost[a] != cost[b]) return cost[a] < cost[b];
        return error[a] < error[b];
    });
    std::vector<std::size_t> front;
    double best = INFINITY;
    for (std::size_t i : order)
        if (error[i] < best) {
            front.push_back(i);
            best = error[i];
        }
    return front;
}

std::optional<std::size_t> cheapestWithin(std::span<const double> cost, std::span<const double> error, double budget,
                                          std::span<const std::size_t> candidates) {
    std::vector<std::size_t> pool(candidates.begin(), candidates.end());
    if (pool.empty()) {
        pool.resize(cost.size());
        std::iota(pool.begin(), pool.end(), std::size_t{0});
    }
    std::optional<std::size_t> best;
    for (std::size_t i : pool)
        if (error[i] <= budget && (!best || cost[i] < cost[*best])) best = i;
    return best;
}

}  // namespace prism::reference
