// The total of a snapshot's counters (see prism/counters/object_counters.hpp).
#include "prism/counters/object_counters.hpp"

#include <numeric>

namespace prism::counters {

std::uint64_t total(std::span<const std::uint64_t> values) {
    return std::accumulate(values.begin(), values.end(), std::uint64_t{0});
}

}  // namespace prism::counters
