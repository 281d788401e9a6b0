// The usage example of prism/counters/object_counters.hpp, compiled and run by tests/snippets.
#include <cstdint>

// [snippet]
#include "prism/counters/object_counters.hpp"
enum class Fruit { Apple, Pear, Count };
// [/snippet]

int main() {
    // [snippet]
    static prism::counters::ObjectCounters<Fruit> fruits;  // one per process, zero at start
    fruits.created(Fruit::Apple);
    fruits.destroyed(Fruit::Apple);
    prism::counters::Counts<Fruit> now = fruits.counts();                     // a snapshot
    std::uint64_t made = now.created(Fruit::Apple), alive = now.liveTotal();  // 1, 0
    // [/snippet]
    return made == 1 && alive == 0 && now.live(Fruit::Pear) == 0 ? 0 : 1;
}
