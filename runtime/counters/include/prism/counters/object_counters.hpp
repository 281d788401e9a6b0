// Process-wide counters of the objects created since start-up and alive now, per kind of an
// enum whose last enumerator is Count: the one mechanism behind prism::gl's and prism::vk's
// objectCounts() (their handles count every object they create and destroy; leak tests
// compare the live counts before and after).
//
// Usage (snippet: examples/snippets/counters_object_counters.cpp):
//
//     #include "prism/counters/object_counters.hpp"
//     enum class Fruit { Apple, Pear, Count };
//     static prism::counters::ObjectCounters<Fruit> fruits;  // one per process, zero at start
//     fruits.created(Fruit::Apple);
//     fruits.destroyed(Fruit::Apple);
//     prism::counters::Counts<Fruit> now = fruits.counts();                     // a snapshot
//     std::uint64_t made = now.created(Fruit::Apple), alive = now.liveTotal();  // 1, 0
//
// Counting is thread-safe (atomics); a snapshot reads each counter once.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

namespace prism::counters {

template <class Kind>
inline constexpr std::size_t kKindCount = static_cast<std::size_t>(Kind::Count);

// The sum of `values`: every live object of every kind.
std::uint64_t total(std::span<const std::uint64_t> values);

// Objects created since start-up and alive now, per kind.
template <class Kind>
struct Counts {
    std::array<std::uint64_t, kKindCount<Kind>> createdByKind{}, liveByKind{};
    std::uint64_t created(Kind kind) const { return createdByKind[static_cast<std::size_t>(kind)]; }
    std::uint64_t live(Kind kind) const { return liveByKind[static_cast<std::size_t>(kind)]; }
    std::uint64_t liveTotal() const { return total(liveByKind); }
};

template <class Kind>
class ObjectCounters {
  public:
    void created(Kind kind) noexcept {
        ++created_[static_cast<std::size_t>(kind)];
        ++live_[static_cast<std::size_t>(kind)];
    }
    void destroyed(Kind kind) noexcept { --live_[static_cast<std::size_t>(kind)]; }
    Counts<Kind> counts() const {
        Counts<Kind> c;
        for (std::size_t k = 0; k < kKindCount<Kind>; ++k) {
            c.createdByKind[k] = created_[k].load();
            c.liveByKind[k] = live_[k].load();
        }
        return c;
    }

  private:
    std::array<std::atomic<std::uint64_t>, kKindCount<Kind>> created_{}, live_{};
};

}  // namespace prism::counters
