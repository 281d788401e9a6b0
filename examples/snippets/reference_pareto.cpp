// The usage example of prism/reference/pareto.hpp, compiled and run by tests/snippets.
#include <vector>

// [snippet]
#include "prism/reference/pareto.hpp"
// [/snippet]

int main() {
    // [snippet]
    const std::vector<double> ms = {1.0, 2.0, 3.0, 2.5}, error = {9.0, 4.0, 1.0, 5.0};
    std::vector<std::size_t> front = prism::reference::paretoFront(ms, error);           // {0, 1, 2}
    std::optional<std::size_t> pick = prism::reference::cheapestWithin(ms, error, 4.5);  // 1
    // [/snippet]
    return front == std::vector<std::size_t>{0, 1, 2} && pick == 1u ? 0 : 1;
}
