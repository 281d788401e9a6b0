// The CPU water step. Every pass mirrors its compute shader in shader_sources/water/
// operation by operation (same fp32 operations in the same order, no fused multiply-add:
// GCC does not contract across statements with -std=c++20 and x86-64 has no FMA without
// -mfma), so the CPU and GPU steps agree bit for bit where the driver rounds as IEEE 754
// says. For speed each pass runs on row bands (row_bands.hpp) and splits the grid into
// the interior, where the loops have no bounds checks and the smoothing runs as unit-
// stride sweeps the compiler vectorises, and a border that keeps the checks. Both compute
// each cell with the same operations in the same order, so the thread count and the split
// change no bit of the water.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

#include "prism/water/water_simulation.hpp"
#include "row_bands.hpp"

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64)
#include <xmmintrin.h>
#define PRISM_WATER_HAVE_MXCSR 1
#endif

namespace prism::water {
namespace {

constexpr float kAvailableFactor = 0.99999904632568359375f;  // 1 - 2^-20 (modules/water/water_grid.glsl)
constexpr float kTan22_5 = 0.41421356f;

// Mesa's llvmpipe runs shaders with denormals flushed to zero (FTZ and DAZ); the
// reference does the same for the duration of a step (the row bands do it per task).
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

// The branch-free helpers below compute every operand first and then select, so the
// compiler can vectorise them; min(a, b) is written as std::min's (b < a) ? b : a and
// max(a, b) as std::max's (a < b) ? b : a, which keeps the selected values (signed zeros
// included) those of the per-cell code.
inline float edgeVelocity(const StepConstants& k, float q0, float sa, float sb, float availA, float availB) {
    const float q1 = (q0 + k.waveAccelDt * (sa - sb)) * k.damping;
    const float saEps = sa + k.epsilon, sbEps = sb + k.epsilon;
    const bool towardsBPositive = q1 > 0.0f;
    const bool blocked = (towardsBPositive & (sb >= saEps)) | (!towardsBPositive & (sa >= sbEps));
    const float q = blocked ? 0.0f : q1;
    const float capA = availA * k.capPerDt;
    const float capB = availB * k.capPerDt;
    const float negCapB = -capB;
    const float towardsB = capA < q ? capA : q;
    const float towardsA = q < negCapB ? negCapB : q;
    return q > 0.0f ? towardsB : towardsA;
}

// One smoothing exchange between cell i (surface si, water ai) and a neighbour j.
inline float smoothExchange(float weight, float si, float ai, float sj, float aj) {
    const float up = weight * (si - sj), capI = weight * ai;
    const float down = weight * (sj - si), capJ = weight * aj;
    const float give = capI < up ? capI : up;
    const float take = capJ < down ? capJ : down;
    return si > sj ? -give : take;
}

// Where a pass writes the water of a cell: the compensated pair and the surface and
// available water the next pass reads (raw pointers, so the compiler can vectorise).
struct WaterOut {
    const float* __restrict terrain;
    float* __restrict hi;
    float* __restrict lo;
    float* __restrict surf;
    float* __restrict avail;
    void operator()(std::size_t i, float h, float l) const {
        hi[i] = h;
        lo[i] = l;
        surf[i] = terrain[i] + h;
        avail[i] = availableWater(h, l);
    }
};

inline std::size_t cellIndex(int x, int z, int W) {
    return static_cast<std::size_t>(z) * static_cast<std::size_t>(W) + static_cast<std::size_t>(x);
}

}  // namespace

CpuWaterSimulation::CpuWaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params)
    : WaterSimulation(std::move(terrain), std::move(permeability), params) {
    threads_ = detail::threadsFor(params_.threads, cellCount());
    if (threads_ > 1) bands_ = std::make_unique<detail::RowBands>(threads_);
    std::vector<glm::vec2> zero(cellCount(), glm::vec2(0.0f));
    resetState(zero);
}

CpuWaterSimulation::~CpuWaterSimulation() = default;

void CpuWaterSimulation::resetState(std::span<const glm::vec2> pairs) {
    const std::size_t n = cellCount();
    hi_.resize(n);
    lo_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        hi_[i] = pairs[i].x;
        lo_[i] = pairs[i].y;
    }
    hiOut_.assign(n, 0.0f);
    loOut_.assign(n, 0.0f);
    surf_.assign(n, 0.0f);
    avail_.assign(n, 0.0f);
    surfOut_.assign(n, 0.0f);
    availOut_.assign(n, 0.0f);
    qEast_.assign(n, 0.0f);
    qSouth_.assign(n, 0.0f);
    flowAmount_.assign(n, 0.0f);
    flowDirection_.assign(n, 4);
    infiltratedRow_.assign(static_cast<std::size_t>(height()), 0.0);
    lostRow_.assign(static_cast<std::size_t>(height()), 0.0);
    infiltrated_ = lost_ = 0.0;
}

std::vector<glm::vec2> CpuWaterSimulation::depthPairs() const {
    std::vector<glm::vec2> out(cellCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {hi_[i], lo_[i]};
    return out;
}

std::vector<glm::vec2> CpuWaterSimulation::edgeVelocities() const {
    std::vector<glm::vec2> out(cellCount());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {qEast_[i], qSouth_[i]};
    return out;
}

void CpuWaterSimulation::lossTotals(double& infiltrated, double& lost) const {
    infiltrated = infiltrated_;
    lost = lost_;
}

void CpuWaterSimulation::swapWater() {
    hi_.swap(hiOut_);
    lo_.swap(loOut_);
    surf_.swap(surfOut_);
    avail_.swap(availOut_);
}

int CpuWaterSimulation::bytesPerCellPerSubstep(bool smoothing) {
    // 4-byte arrays. A pass that writes water reads hi, lo and the terrain and writes hi,
    // lo, surface and available water: 28 bytes, besides the arrays of its own.
    constexpr int kWater = 12 + 16;
    constexpr int kRain = 4 + kWater;       // + permeability
    constexpr int kFlowOut = 8 + 8;         // surface, available -> amount, code
    constexpr int kGather = 8 + kWater;     // + amount, code
    constexpr int kVelocity = 8 + 8 + 8;    // surface, available; q east and south read and written
    constexpr int kApply = 8 + kWater;      // + q east and south
    constexpr int kSmoothing = 8 + kWater;  // + surface, available
    return kRain + kFlowOut + kGather + kVelocity + kApply + (smoothing ? kSmoothing : 0);
}

void CpuWaterSimulation::runSubsteps(const StepConstants& k, long count) {
    FlushDenormals ftz;
    for (long s = 0; s < count; ++s) substep(k);
}

void CpuWaterSimulation::substep(const StepConstants& k) {
    const int H = height();
    auto pass = [&](auto&& body) {
        const std::function<void(int, int)> task = body;
        if (bands_)
            bands_->run(H, task);
        else
            task(0, H);
    };
    pass([&](int z0, int z1) { rainAndInfiltration(k, z0, z1); });
    swapWater();
    pass([&](int z0, int z1) { tangentialFlowOut(k, z0, z1); });
    pass([&](int z0, int z1) { tangentialFlowGather(z0, z1); });
    swapWater();
    pass([&](int z0, int z1) { distributionVelocity(k, z0, z1); });
    pass([&](int z0, int z1) { distributionApply(k, z0, z1); });
    swapWater();
    if (k.smoothRadius > 0) {
        pass([&](int z0, int z1) { smoothing(k, z0, z1); });
        swapWater();
    }
    double inf = 0.0, lost = 0.0;
    for (int z = 0; z < H; ++z) {
        inf += infiltratedRow_[static_cast<std::size_t>(z)];
        lost += lostRow_[static_cast<std::size_t>(z)];
    }
    infiltrated_ += inf;
    lost_ += lost;
}

// 1 + 2 (water_rain_infiltrate.comp): infiltration takes permeability x dt, or all of the
// (compensated) water when that is as much, so a cell is emptied exactly, never below zero.
void CpuWaterSimulation::rainAndInfiltration(const StepConstants& k, int z0, int z1) {
    const WaterOut write{terrain_.heights.data(), hiOut_.data(), loOut_.data(), surfOut_.data(), availOut_.data()};
    const float* __restrict hiIn = hi_.data();
    const float* __restrict loIn = lo_.data();
    const int W = width();
    // What each cell of the row gave up, as (hi, lo) floats: the cell's whole water when
    // emptied, else (capacity, +0); summed below in double in cell order, as h + l.
    thread_local std::vector<float> takenHi, takenLo;
    takenHi.resize(static_cast<std::size_t>(W));
    takenLo.resize(static_cast<std::size_t>(W));
    for (int z = z0; z < z1; ++z) {
        const std::size_t row = cellIndex(0, z, W);
        for (int x = 0; x < W; ++x) {
            const std::size_t i = row + static_cast<std::size_t>(x);
            float h = hiIn[i], l = loIn[i];
            dfAdd(h, l, k.rainDepth);
            const float capacity = permeability_[i] * k.dt;
            float hLeft = h, lLeft = l;
            dfAdd(hLeft, lLeft, -capacity);
            const bool emptied = capacity >= availableWater(h, l);
            takenHi[static_cast<std::size_t>(x)] = emptied ? h : capacity;
            takenLo[static_cast<std::size_t>(x)] = emptied ? l : 0.0f;
            write(i, emptied ? 0.0f : hLeft, emptied ? 0.0f : lLeft);
        }
        double infiltrated = 0.0;
        for (std::size_t x = 0; x < static_cast<std::size_t>(W); ++x)
            infiltrated += static_cast<double>(takenHi[x]) + static_cast<double>(takenLo[x]);
        infiltratedRow_[static_cast<std::size_t>(z)] = infiltrated;
    }
}

// 3a (water_flow_out.comp): the Sobel gradient of the surface picks the downhill Moore
// neighbour; interior cells read their 8 neighbours directly, border cells clamp.
void CpuWaterSimulation::tangentialFlowOut(const StepConstants& k, int z0, int z1) {
    const int W = width(), H = height();
    for (int z = z0; z < z1; ++z) {
        if (z == 0 || z == H - 1 || W < 3) {
            for (int x = 0; x < W; ++x) flowOutCell(k, x, z);
            continue;
        }
        flowOutCell(k, 0, z);
        flowOutInteriorRow(k, z);
        flowOutCell(k, W - 1, z);
    }
}

// The decision for one cell, with clamped neighbours and a target that may be off the map.
void CpuWaterSimulation::flowOutCell(const StepConstants& k, int x, int z) {
    const int W = width(), H = height();
    const float* b = terrain_.heights.data();
    const float* s = surf_.data();
    auto at = [&](int cx, int cz) { return s[cellIndex(std::clamp(cx, 0, W - 1), std::clamp(cz, 0, H - 1), W)]; };
    const float nw = at(x - 1, z - 1), n = at(x, z - 1), ne = at(x + 1, z - 1), w = at(x - 1, z), e = at(x + 1, z);
    const float sw = at(x - 1, z + 1), so = at(x, z + 1), se = at(x + 1, z + 1);
    const std::size_t i = cellIndex(x, z, W);
    const float gx = ((ne + 2.0f * e + se) - (nw + 2.0f * w + sw)) * k.invEightCell;
    const float gz = ((sw + 2.0f * so + se) - (nw + 2.0f * n + ne)) * k.invEightCell;
    const float slope = std::sqrt(gx * gx + gz * gz);
    const float dx = -gx, dz = -gz;
    const int ox = std::abs(dx) > kTan22_5 * std::abs(dz) ? signOf(dx) : 0;
    const int oz = std::abs(dz) > kTan22_5 * std::abs(dx) ? signOf(dz) : 0;
    float amount = 0.0f;
    int code = 4;
    const int tx = x + ox, tz = z + oz;
    const bool inside = tx >= 0 && tz >= 0 && tx < W && tz < H;
    if ((ox != 0 || oz != 0) && slope > 0.0f && (inside || k.openBorder != 0)) {
        const float si = s[i];
        const float st = inside ? s[cellIndex(tx, tz, W)] : b[i];
        const float fraction = std::min(k.maxFlowFraction, k.flowRateDt * slope);
        const float a = fraction * avail_[i];
        const float drop = std::max(0.0f, (si - st) * 0.5f);
        amount = std::min(a, drop);
        code = (oz + 1) * 3 + (ox + 1);
    }
    flowAmount_[i] = amount;
    flowDirection_[i] = static_cast<std::int32_t>(code);
}

// Interior: every target is inside; the same decision as flowOutCell(), branch-free, so the
// loop vectorises (the trip count and the pointers are locals that stay in registers).
void CpuWaterSimulation::flowOutInteriorRow(const StepConstants& k, int z) {
    const int W = width();
    const std::size_t w = static_cast<std::size_t>(W);
    const std::size_t row = cellIndex(0, z, W);
    const float* __restrict c = surf_.data() + row;
    const float* __restrict up = c - w;
    const float* __restrict down = c + w;
    const float* __restrict avail = avail_.data() + row;
    float* __restrict amountOut = flowAmount_.data() + row;
    std::int32_t* __restrict codeOut = flowDirection_.data() + row;
    const int interiorEnd = W - 1;
    for (int x = 1; x < interiorEnd; ++x) {
        const float nw = up[x - 1], n = up[x], ne = up[x + 1], we = c[x - 1], e = c[x + 1];
        const float sw = down[x - 1], so = down[x], se = down[x + 1], si = c[x];
        const float gx = ((ne + 2.0f * e + se) - (nw + 2.0f * we + sw)) * k.invEightCell;
        const float gz = ((sw + 2.0f * so + se) - (nw + 2.0f * n + ne)) * k.invEightCell;
        const float slope = std::sqrt(gx * gx + gz * gz);
        const float dx = -gx, dz = -gz;
        const float adx = std::abs(dx), adz = std::abs(dz);
        // ox, oz as flowOutCell(): the sign of the component that is not too small; the
        // target's surface picked by masks (written as chained selects so the loop
        // vectorises).
        const bool useX = adx > kTan22_5 * adz, useZ = adz > kTan22_5 * adx;
        const bool xPos = useX & (dx > 0.0f), xNeg = useX & (dx < 0.0f);
        const bool zPos = useZ & (dz > 0.0f), zNeg = useZ & (dz < 0.0f);
        const int ox = static_cast<int>(xPos) - static_cast<int>(xNeg);
        const int oz = static_cast<int>(zPos) - static_cast<int>(zNeg);
        float northRow = n;
        northRow = xNeg ? nw : northRow;
        northRow = xPos ? ne : northRow;
        float centreRow = si;
        centreRow = xNeg ? we : centreRow;
        centreRow = xPos ? e : centreRow;
        float southRow = so;
        southRow = xNeg ? sw : southRow;
        southRow = xPos ? se : southRow;
        float st = centreRow;
        st = zNeg ? northRow : st;
        st = zPos ? southRow : st;
        const float flow = k.flowRateDt * slope;
        const float fraction = flow < k.maxFlowFraction ? flow : k.maxFlowFraction;
        const float a = fraction * avail[x];
        const float half = (si - st) * 0.5f;
        const float drop = 0.0f < half ? half : 0.0f;
        const float amount = drop < a ? drop : a;
        const bool moves = ((ox != 0) | (oz != 0)) & (slope > 0.0f);
        amountOut[x] = moves ? amount : 0.0f;
        codeOut[x] = static_cast<std::int32_t>(moves ? (oz + 1) * 3 + (ox + 1) : 4);
    }
}

// 3b (water_flow_gather.comp): each cell adds what its neighbours send it and subtracts
// what it sends; water sent off an open border is counted as lost.
void CpuWaterSimulation::tangentialFlowGather(int z0, int z1) {
    const int W = width(), H = height();
    for (int z = z0; z < z1; ++z) {
        double lostRow = 0.0;
        if (z == 0 || z == H - 1 || W < 3) {
            for (int x = 0; x < W; ++x) lostRow += gatherCell(x, z);
            lostRow_[static_cast<std::size_t>(z)] = lostRow;
            continue;
        }
        lostRow += gatherCell(0, z);
        gatherInteriorRow(z);
        lostRow += gatherCell(W - 1, z);
        lostRow_[static_cast<std::size_t>(z)] = lostRow;
    }
}

// One cell with every neighbour checked against the map's edges.
float CpuWaterSimulation::gatherCell(int x, int z) {
    const WaterOut write{terrain_.heights.data(), hiOut_.data(), loOut_.data(), surfOut_.data(), availOut_.data()};
    const int W = width(), H = height();
    const float* amountOf = flowAmount_.data();
    const std::int32_t* codeOf = flowDirection_.data();
    auto inside = [&](int cx, int cz) { return cx >= 0 && cz >= 0 && cx < W && cz < H; };
    const std::size_t i = cellIndex(x, z, W);
    float net = 0.0f, lost = 0.0f;
    const int code = codeOf[i];
    if (code != 4 && amountOf[i] > 0.0f) {
        net = -amountOf[i];
        if (!inside(x + code % 3 - 1, z + code / 3 - 1)) lost = amountOf[i];
    }
    for (int oz = -1; oz <= 1; ++oz)
        for (int ox = -1; ox <= 1; ++ox) {
            if (ox == 0 && oz == 0) continue;
            const int nx = x + ox, nz = z + oz;
            if (!inside(nx, nz)) continue;
            const std::size_t j = cellIndex(nx, nz, W);
            const int ncode = codeOf[j];
            if (ncode != 4 && ncode % 3 - 1 == -ox && ncode / 3 - 1 == -oz) net = net + amountOf[j];
        }
    float h = hi_[i], l = lo_[i];
    dfAdd(h, l, net);
    write(i, h, l);
    return lost;
}

// Interior: every target is inside, nothing is lost. A neighbour at (ox, oz) sends here when
// its code points back: (1 - oz) * 3 + (1 - ox). Adding +0 for a neighbour that sends
// nothing changes no bit: net is never -0 (it starts at +0 or below zero, and amounts are
// >= +0). Branch-free with local restrict pointers, so the loop vectorises.
void CpuWaterSimulation::gatherInteriorRow(int z) {
    const WaterOut put{terrain_.heights.data(), hiOut_.data(), loOut_.data(), surfOut_.data(), availOut_.data()};
    const int W = width();
    const std::size_t w = static_cast<std::size_t>(W);
    const std::size_t row = cellIndex(0, z, W);
    const float* __restrict am = flowAmount_.data() + row;
    const float* __restrict amN = am - w;
    const float* __restrict amS = am + w;
    const std::int32_t* __restrict cd = flowDirection_.data() + row;
    const std::int32_t* __restrict cdN = cd - w;
    const std::int32_t* __restrict cdS = cd + w;
    const float* __restrict hiRow = hi_.data();
    const float* __restrict loRow = lo_.data();
    const int interiorEnd = W - 1;
    for (int x = 1; x < interiorEnd; ++x) {
        // Every amount is loaded first, so the selects need no conditional loads.
        const float out = am[x], fromNw = amN[x - 1], fromN = amN[x], fromNe = amN[x + 1];
        const float fromW = am[x - 1], fromE = am[x + 1], fromSw = amS[x - 1], fromS = amS[x], fromSe = amS[x + 1];
        float net = ((cd[x] != 4) & (out > 0.0f)) ? -out : 0.0f;
        net = net + (cdN[x - 1] == 8 ? fromNw : 0.0f);
        net = net + (cdN[x] == 7 ? fromN : 0.0f);
        net = net + (cdN[x + 1] == 6 ? fromNe : 0.0f);
        net = net + (cd[x - 1] == 5 ? fromW : 0.0f);
        net = net + (cd[x + 1] == 3 ? fromE : 0.0f);
        net = net + (cdS[x - 1] == 2 ? fromSw : 0.0f);
        net = net + (cdS[x] == 1 ? fromS : 0.0f);
        net = net + (cdS[x + 1] == 0 ? fromSe : 0.0f);
        const std::size_t i = row + static_cast<std::size_t>(x);
        float h = hiRow[i], l = loRow[i];
        dfAdd(h, l, net);
        put(i, h, l);
    }
}

// 4a (water_distribute_velocity.comp)
void CpuWaterSimulation::distributionVelocity(const StepConstants& k, int z0, int z1) {
    const int W = width(), H = height();
    const float* s = surf_.data();
    const float* a = avail_.data();
    for (int z = z0; z < z1; ++z) {
        const std::size_t row = cellIndex(0, z, W);
        float* east = qEast_.data() + row;
        for (int x = 0; x + 1 < W; ++x) {
            const std::size_t i = row + static_cast<std::size_t>(x);
            east[x] = edgeVelocity(k, east[x], s[i], s[i + 1], a[i], a[i + 1]);
        }
        if (z + 1 < H) {
            float* south = qSouth_.data() + row;
            const std::size_t w = static_cast<std::size_t>(W);
            for (int x = 0; x < W; ++x) {
                const std::size_t i = row + static_cast<std::size_t>(x);
                south[x] = edgeVelocity(k, south[x], s[i], s[i + w], a[i], a[i + w]);
            }
        }
    }
}

// 4b (water_distribute_apply.comp)
void CpuWaterSimulation::distributionApply(const StepConstants& k, int z0, int z1) {
    const WaterOut write{terrain_.heights.data(), hiOut_.data(), loOut_.data(), surfOut_.data(), availOut_.data()};
    const float* __restrict hiIn = hi_.data();
    const float* __restrict loIn = lo_.data();
    const int W = width(), H = height();
    const std::size_t w = static_cast<std::size_t>(W);
    auto cell = [&](int x, int z) {
        const std::size_t i = cellIndex(x, z, W);
        const float te = x + 1 < W ? qEast_[i] * k.dt : 0.0f;
        const float ts = z + 1 < H ? qSouth_[i] * k.dt : 0.0f;
        const float tw = x > 0 ? qEast_[i - 1] * k.dt : 0.0f;
        const float tn = z > 0 ? qSouth_[i - w] * k.dt : 0.0f;
        const float net = (tw + tn) - (te + ts);
        float h = hiIn[i], l = loIn[i];
        dfAdd(h, l, net);
        write(i, h, l);
    };
    for (int z = z0; z < z1; ++z) {
        if (z == 0 || z == H - 1 || W < 3) {
            for (int x = 0; x < W; ++x) cell(x, z);
            continue;
        }
        cell(0, z);
        const std::size_t row = cellIndex(0, z, W);
        const float* __restrict east = qEast_.data() + row;
        const float* __restrict south = qSouth_.data() + row;
        const float* __restrict north = qSouth_.data() + row - w;
        // Locals the lambdas do not capture (by reference): the trip count and the
        // pointers stay in registers, so the loop vectorises.
        const int interiorEnd = W - 1;
        const float dt = k.dt;
        const float* __restrict hiRow = hiIn + row;
        const float* __restrict loRow = loIn + row;
        const float* __restrict ground = terrain_.heights.data() + row;
        float* __restrict hiDst = hiOut_.data() + row;
        float* __restrict loDst = loOut_.data() + row;
        float* __restrict surfDst = surfOut_.data() + row;
        float* __restrict availDst = availOut_.data() + row;
        for (int x = 1; x < interiorEnd; ++x) {
            const float net = (east[x - 1] * dt + north[x] * dt) - (east[x] * dt + south[x] * dt);
            float h = hiRow[x], l = loRow[x];
            dfAdd(h, l, net);
            hiDst[x] = h;
            loDst[x] = l;
            surfDst[x] = ground[x] + h;
            availDst[x] = availableWater(h, l);
        }
        cell(W - 1, z);
    }
}

// 5 (water_smooth.comp): pairwise exchanges with the (2r+1)^2 neighbours, in the order
// dz, dx. Interior rows sweep each neighbour offset over the row (unit stride,
// vectorised), accumulating into one sum per cell in the same order as the per-cell loop.
void CpuWaterSimulation::smoothing(const StepConstants& k, int z0, int z1) {
    const WaterOut write{terrain_.heights.data(), hiOut_.data(), loOut_.data(), surfOut_.data(), availOut_.data()};
    const float* __restrict hiIn = hi_.data();
    const float* __restrict loIn = lo_.data();
    const int W = width(), H = height(), r = k.smoothRadius;
    const float* s = surf_.data();
    const float* a = avail_.data();
    auto cell = [&](int x, int z) {
        const std::size_t i = cellIndex(x, z, W);
        float net = 0.0f;
        for (int dz = -r; dz <= r; ++dz) {
            const int nz = z + dz;
            if (nz < 0 || nz >= H) continue;
            for (int dx = -r; dx <= r; ++dx) {
                if (dx == 0 && dz == 0) continue;
                const int nx = x + dx;
                if (nx < 0 || nx >= W) continue;
                const std::size_t j = cellIndex(nx, nz, W);
                const float weight = k.smoothWeights[static_cast<std::size_t>(std::abs(dz) * 8 + std::abs(dx))];
                net = net + smoothExchange(weight, s[i], a[i], s[j], a[j]);
            }
        }
        float h = hiIn[i], l = loIn[i];
        dfAdd(h, l, net);
        write(i, h, l);
    };
    thread_local std::vector<float> netRow;
    netRow.assign(static_cast<std::size_t>(W), 0.0f);
    for (int z = z0; z < z1; ++z) {
        if (z < r || z >= H - r || W <= 2 * r) {
            for (int x = 0; x < W; ++x) cell(x, z);
            continue;
        }
        for (int x = 0; x < r; ++x) cell(x, z);
        const std::size_t row = cellIndex(0, z, W);
        const float* __restrict si = s + row;
        const float* __restrict ai = a + row;
        float* __restrict net = netRow.data();
        for (int x = r; x < W - r; ++x) net[x] = 0.0f;
        for (int dz = -r; dz <= r; ++dz) {
            const float* __restrict sj = s + cellIndex(0, z + dz, W);
            const float* __restrict aj = a + cellIndex(0, z + dz, W);
            for (int dx = -r; dx <= r; ++dx) {
                if (dx == 0 && dz == 0) continue;
                const float weight = k.smoothWeights[static_cast<std::size_t>(std::abs(dz) * 8 + std::abs(dx))];
                for (int x = r; x < W - r; ++x)
                    net[x] = net[x] + smoothExchange(weight, si[x], ai[x], sj[x + dx], aj[x + dx]);
            }
        }
        for (int x = r; x < W - r; ++x) {
            const std::size_t i = row + static_cast<std::size_t>(x);
            float h = hiIn[i], l = loIn[i];
            dfAdd(h, l, net[x]);
            write(i, h, l);
        }
        for (int x = W - r; x < W; ++x) cell(x, z);
    }
}

}  // namespace prism::water
