// Internal: argument checks shared by the procedural mesh generators, throwing
// std::invalid_argument that names the generator and the parameter. Not installed.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace prism::geometry::detail {

inline void requirePositiveSize(const char* generator, const char* parameter, float value) {
    if (!(std::isfinite(value) && value > 0.0f))
        throw std::invalid_argument(std::string(generator) + ": " + parameter + " must be a finite number > 0, got " +
                                    std::to_string(value));
}

inline void requireInRange(const char* generator, const char* parameter, float value, float low, float high) {
    if (!(value >= low && value <= high))
        throw std::invalid_argument(std::string(generator) + ": " + parameter + " must be in [" + std::to_string(low) +
                                    ", " + std::to_string(high) + "], got " + std::to_string(value));
}

inline void requireCountInRange(const char* generator, const char* parameter, std::uint32_t value, std::uint32_t low,
                                std::uint32_t high) {
    if (value < low || value > high)
        throw std::invalid_argument(std::string(generator) + ": " + parameter + " must be in [" + std::to_string(low) +
                                    ", " + std::to_string(high) + "], got " + std::to_string(value));
}

// Generous upper bound for segment counts: keeps vertex counts well inside uint32.
inline constexpr std::uint32_t kMaxSegments = 16384;

}  // namespace prism::geometry::detail
