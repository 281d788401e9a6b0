// The first CPU water step, kept unchanged as the test reference for the fast one:
// plain single-threaded per-cell loops, each pass written like its compute shader in
// shader_sources/water/ (see reference_water_step.hpp).
#include <algorithm>
#include <cmath>
#include <cstring>

#include <stdexcept>

#include "reference_water_step.hpp"

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64)
#include <xmmintrin.h>
#define PRISM_WATER_HAVE_MXCSR 1
#endif

namespace prism::water::test {
namespace {

constexpr float kAvailableFactor = 0.99999904632568359375f;  // 1 - 2^-20 (modules/water/water_grid.glsl)
constexpr float kTan22_5 = 0.41421356f;

// Mesa's llvmpipe runs shaders with denormals flushed to zero (FTZ and DAZ); the
// reference does the same for the duration of a step.
class FlushDenormals {
  public:
#ifdef PRISM_WATER_HAVE_MXCSR
    FlushDenormals() : saved_(_mm_getcsr()) {
        _mm_setcsr(saved_ | 0x8040u);
    }
    ~FlushDenormals() {
        _mm_setcsr(saved_);
    }

  private:
    unsigned saved_;
#endif
};

inline void twoSum(float a, float b, float& s, float& e) {
    s = a + b;
    const float bb = s - a;
    e = (a - (s - bb)) + (b - bb);
}

inline void dfAdd(float& hi, float& lo, float d) {
    float s, e;
    twoSum(hi, d, s, e);
    const float l = e + lo;
    const float h = s + l;
    lo = l - (h - s);
    hi = h;
}

inline float availableWater(float hi, float lo) {
    const float v = hi + lo;
    const float a = v * kAvailableFactor;
    return v > 0.0f ? a : 0.0f;
}

inline int signOf(float v) {
    return v > 0.0f ? 1 : (v < 0.0f ? -1 : 0);
}

inline float edgeVelocity(const StepConstants& k, float q0, float sa, float sb, float availA, float availB) {
    float q = (q0 + k.waveAccelDt * (sa - sb)) * k.damping;
    if (q > 0.0f ? (sb >= sa + k.epsilon) : (sa >= sb + k.epsilon)) q = 0.0f;
    const float capA = availA * k.capPerDt;
    const float capB = availB * k.capPerDt;
    return q > 0.0f ? std::min(q, capA) : std::max(q, -capB);
}

}  // namespace

ReferenceWaterSimulation::ReferenceWaterSimulation(HeightField terrain, std::vector<float> permeability,
                                                   WaterParams params)
    : WaterSimulation(std::move(terrain), std::move(permeability), params) {
    std::vector<glm::vec2> zero(cellCount(), glm::vec2(0.0f));
    resetState(zero);
}

void ReferenceWaterSimulation::resetState(std::span<const glm::vec2> pairs) {
    const std::size_t n = cellCount();
    hi_.resize(n);
    lo_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        hi_[i] = pairs[i].x;
        lo_[i] = pairs[i].y;
    }
    hiOut_.assign(n, 0.0f);
    loOut_.assign(n, 0.0f);
    qEast_.assign(n, 0.0f);
    qSouth_.assign(n, 0.0f);
    flowAmount_.assign(n, 0.0f);
    flowDirection_.assign(n, 4);
    infiltratedStep_.assign(n, 0.0f);
    lostStep_.assign(n, 0.0f);
    infiltrated_ = lost_ = 0.0;
}

std::vector<glm::vec2> ReferenceWaterSimulation::depthPairs() const {
    std::vector<glm::vec2> out(cellCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {hi_[i], lo_[i]};
    return out;
}

std::vector<glm::vec2> ReferenceWaterSimulation::edgeVelocities() const {
    std::vector<glm::vec2> out(cellCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {qEast_[i], qSouth_[i]};
    return out;
}

void ReferenceWaterSimulation::lossTotals(double& infiltrated, double& lost) const {
    infiltrated = infiltrated_;
    lost = lost_;
}

void ReferenceWaterSimulation::swapWater() {
    hi_.swap(hiOut_);
    lo_.swap(loOut_);
}

void ReferenceWaterSimulation::runSubsteps(const StepConstants& k, long count) {
    FlushDenormals ftz;
    for (long s = 0; s < count; ++s) substep(k);
}

void ReferenceWaterSimulation::substep(const StepConstants& k) {
    rainAndInfiltration(k);
    tangentialFlowOut(k);
    tangentialFlowGather();
    distributionVelocity(k);
    distributionApply(k);
    if (k.smoothRadius > 0) smoothing(k);
    double inf = 0.0, lost = 0.0;
    for (std::size_t i = 0; i < cellCount(); ++i) {
        inf += infiltratedStep_[i];
        lost += lostStep_[i];
    }
    infiltrated_ += inf;
    lost_ += lost;
}

// 1 + 2 (water_rain_infiltrate.comp): infiltration takes permeability x dt, or all of the
// (compensated) water when that is as much, so a cell is emptied exactly, never below zero.
void ReferenceWaterSimulation::rainAndInfiltration(const StepConstants& k) {
    const std::size_t n = cellCount();
    for (std::size_t i = 0; i < n; ++i) {
        float h = hi_[i], l = lo_[i];
        dfAdd(h, l, k.rainDepth);
        const float capacity = permeability_[i] * k.dt;
        if (capacity >= availableWater(h, l)) {
            infiltratedStep_[i] = static_cast<double>(h) + static_cast<double>(l);
            h = l = 0.0f;
        } else {
            infiltratedStep_[i] = capacity;
            dfAdd(h, l, -capacity);
        }
        hiOut_[i] = h;
        loOut_[i] = l;
        lostStep_[i] = 0.0f;
    }
    swapWater();
}

// 3a (water_flow_out.comp)
void ReferenceWaterSimulation::tangentialFlowOut(const StepConstants& k) {
    const int W = width(), H = height();
    const float* b = terrain_.heights.data();
    auto surfaceAt = [&](int x, int z) {
        x = std::clamp(x, 0, W - 1);
        z = std::clamp(z, 0, H - 1);
        const std::size_t j = static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
        const float s = b[j] + hi_[j];
        return s;
    };
    for (int z = 0; z < H; ++z)
        for (int x = 0; x < W; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
            const float nw = surfaceAt(x - 1, z - 1), n = surfaceAt(x, z - 1), ne = surfaceAt(x + 1, z - 1);
            const float w = surfaceAt(x - 1, z), e = surfaceAt(x + 1, z);
            const float sw = surfaceAt(x - 1, z + 1), s = surfaceAt(x, z + 1), se = surfaceAt(x + 1, z + 1);
            const float gx = ((ne + 2.0f * e + se) - (nw + 2.0f * w + sw)) * k.invEightCell;
            const float gz = ((sw + 2.0f * s + se) - (nw + 2.0f * n + ne)) * k.invEightCell;
            const float slope = std::sqrt(gx * gx + gz * gz);
            const float dx = -gx, dz = -gz;
            const int ox = std::abs(dx) > kTan22_5 * std::abs(dz) ? signOf(dx) : 0;
            const int oz = std::abs(dz) > kTan22_5 * std::abs(dx) ? signOf(dz) : 0;
            float amount = 0.0f;
            int code = 4;
            const int tx = x + ox, tz = z + oz;
            const bool inside = tx >= 0 && tz >= 0 && tx < W && tz < H;
            if ((ox != 0 || oz != 0) && slope > 0.0f && (inside || k.openBorder != 0)) {
                const float si = b[i] + hi_[i];
                const std::size_t t =
                    inside ? static_cast<std::size_t>(tz) * static_cast<std::size_t>(W) + static_cast<std::size_t>(tx)
                           : i;
                const float st = inside ? b[t] + hi_[t] : b[i];
                const float fraction = std::min(k.maxFlowFraction, k.flowRateDt * slope);
                const float a = fraction * availableWater(hi_[i], lo_[i]);
                const float drop = std::max(0.0f, (si - st) * 0.5f);
                amount = std::min(a, drop);
                code = (oz + 1) * 3 + (ox + 1);
            }
            flowAmount_[i] = amount;
            flowDirection_[i] = code;
        }
}

// 3b (water_flow_gather.comp)
void ReferenceWaterSimulation::tangentialFlowGather() {
    const int W = width(), H = height();
    auto inside = [&](int x, int z) { return x >= 0 && z >= 0 && x < W && z < H; };
    for (int z = 0; z < H; ++z)
        for (int x = 0; x < W; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
            const int code = flowDirection_[i];
            float net = 0.0f, lost = 0.0f;
            if (code != 4 && flowAmount_[i] > 0.0f) {
                net = -flowAmount_[i];
                if (!inside(x + code % 3 - 1, z + code / 3 - 1)) lost = flowAmount_[i];
            }
            for (int oz = -1; oz <= 1; ++oz)
                for (int ox = -1; ox <= 1; ++ox) {
                    if (ox == 0 && oz == 0) continue;
                    const int nx = x + ox, nz = z + oz;
                    if (!inside(nx, nz)) continue;
                    const std::size_t j =
                        static_cast<std::size_t>(nz) * static_cast<std::size_t>(W) + static_cast<std::size_t>(nx);
                    const int ncode = flowDirection_[j];
                    if (ncode != 4 && ncode % 3 - 1 == -ox && ncode / 3 - 1 == -oz) net = net + flowAmount_[j];
                }
            float h = hi_[i], l = lo_[i];
            dfAdd(h, l, net);
            hiOut_[i] = h;
            loOut_[i] = l;
            lostStep_[i] = lost;
        }
    swapWater();
}

// 4a (water_distribute_velocity.comp)
void ReferenceWaterSimulation::distributionVelocity(const StepConstants& k) {
    const int W = width(), H = height();
    const float* b = terrain_.heights.data();
    for (int z = 0; z < H; ++z)
        for (int x = 0; x < W; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
            const float si = b[i] + hi_[i];
            const float ai = availableWater(hi_[i], lo_[i]);
            if (x + 1 < W) {
                const std::size_t j = i + 1;
                const float sj = b[j] + hi_[j];
                qEast_[i] = edgeVelocity(k, qEast_[i], si, sj, ai, availableWater(hi_[j], lo_[j]));
            }
            if (z + 1 < H) {
                const std::size_t j = i + static_cast<std::size_t>(W);
                const float sj = b[j] + hi_[j];
                qSouth_[i] = edgeVelocity(k, qSouth_[i], si, sj, ai, availableWater(hi_[j], lo_[j]));
            }
        }
}

// 4b (water_distribute_apply.comp)
void ReferenceWaterSimulation::distributionApply(const StepConstants& k) {
    const int W = width(), H = height();
    for (int z = 0; z < H; ++z)
        for (int x = 0; x < W; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
            const float te = x + 1 < W ? qEast_[i] * k.dt : 0.0f;
            const float ts = z + 1 < H ? qSouth_[i] * k.dt : 0.0f;
            const float tw = x > 0 ? qEast_[i - 1] * k.dt : 0.0f;
            const float tn = z > 0 ? qSouth_[i - static_cast<std::size_t>(W)] * k.dt : 0.0f;
            const float net = (tw + tn) - (te + ts);
            float h = hi_[i], l = lo_[i];
            dfAdd(h, l, net);
            hiOut_[i] = h;
            loOut_[i] = l;
        }
    swapWater();
}

// 5 (water_smooth.comp)
void ReferenceWaterSimulation::smoothing(const StepConstants& k) {
    const int W = width(), H = height(), r = k.smoothRadius;
    const float* b = terrain_.heights.data();
    for (int z = 0; z < H; ++z)
        for (int x = 0; x < W; ++x) {
            const std::size_t i =
                static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
            const float si = b[i] + hi_[i];
            const float ai = availableWater(hi_[i], lo_[i]);
            float net = 0.0f;
            for (int dz = -r; dz <= r; ++dz) {
                const int nz = z + dz;
                if (nz < 0 || nz >= H) continue;
                for (int dx = -r; dx <= r; ++dx) {
                    if (dx == 0 && dz == 0) continue;
                    const int nx = x + dx;
                    if (nx < 0 || nx >= W) continue;
                    const std::size_t j =
                        static_cast<std::size_t>(nz) * static_cast<std::size_t>(W) + static_cast<std::size_t>(nx);
                    const float weight = k.smoothWeights[static_cast<std::size_t>(std::abs(dz) * 8 + std::abs(dx))];
                    const float sj = b[j] + hi_[j];
                    float t;
                    if (si > sj) {
                        const float a = weight * (si - sj);
                        const float c = weight * ai;
                        t = -std::min(a, c);
                    } else {
                        const float a = weight * (sj - si);
                        const float c = weight * availableWater(hi_[j], lo_[j]);
                        t = std::min(a, c);
                    }
                    net = net + t;
                }
            }
            float h = hi_[i], l = lo_[i];
            dfAdd(h, l, net);
            hiOut_[i] = h;
            loOut_[i] = l;
        }
    swapWater();
}

}  // namespace prism::water::test
