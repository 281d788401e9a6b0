// Checks shared by the CPU and GPU rain tests: every particle finite and inside the
// cylinder around the camera, and the level-of-detail histogram.
#pragma once

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "prism/rain/rain_params.hpp"
#include "prism/rain/rain_simulation.hpp"

namespace prism::rain::test {

// Relative slack for float rounding of positions (world coordinates up to ~1e5 m).
inline float insideSlack(const glm::vec3& center) {
    return 1e-4f + 2e-6f * (std::fabs(center.x) + std::fabs(center.y) + std::fabs(center.z));
}

inline ::testing::AssertionResult allFiniteAndInside(std::span<const Particle> particles, const glm::vec3& center,
                                                     float radius, float height) {
    const float slack = insideSlack(center);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(p.position[c]) || !std::isfinite(p.seed[c]) || !std::isfinite(p.velocity[c]))
                return ::testing::AssertionFailure() << "particle " << i << " is not finite";
        const glm::vec3 local = glm::vec3(p.position) - center;
        const float r = std::sqrt(local.x * local.x + local.z * local.z);
        if (r > radius * (1.0f + 1e-5f) + slack)
            return ::testing::AssertionFailure()
                   << "particle " << i << " is " << r << " m from the axis (radius " << radius << ")";
        if (local.y < -0.5f * height - slack || local.y > 0.5f * height + slack)
            return ::testing::AssertionFailure() << "particle " << i << " is at height " << local.y
                                                 << " relative to the centre (half height " << 0.5f * height << ")";
    }
    return ::testing::AssertionSuccess();
}

// Share of particles in each LOD ring by their current horizontal distance.
inline std::vector<double> ringShares(std::span<const Particle> particles, const glm::vec3& center, float radius,
                                      int rings) {
    std::vector<double> share(static_cast<std::size_t>(rings), 0.0);
    for (const auto& p : particles) {
        const float dx = p.position.x - center.x, dz = p.position.z - center.z;
        const int k =
            std::min(rings - 1, static_cast<int>(std::sqrt(dx * dx + dz * dz) / radius * static_cast<float>(rings)));
        share[static_cast<std::size_t>(k)] += 1.0;
    }
    for (auto& s : share) s /= std::max<double>(1.0, static_cast<double>(particles.size()));
    return share;
}

// The expected share of ring k: falloff^k (2k + 1) / sum.
inline std::vector<double> expectedRingShares(int rings, float falloff) {
    std::vector<double> share;
    double sum = 0.0, w = 1.0;
    for (int k = 0; k < rings; ++k) {
        share.push_back(w * (2 * k + 1));
        sum += share.back();
        w *= falloff;
    }
    for (auto& s : share) s /= sum;
    return share;
}

}  // namespace prism::rain::test
