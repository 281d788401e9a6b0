// The passes of the CPU water step, one row at a time (see water_rows.hpp). Each pass
// mirrors its compute shader in shader_sources/water/ operation by operation (same fp32
// operations in the same order, no fused multiply-add: GCC does not contract across
// statements with -std=c++20 and x86-64 has no FMA without -mfma), so the CPU and GPU
// steps agree bit for bit where the driver rounds as IEEE 754 says. A row's interior
// cells run in loops without bounds checks whose selects are branch-free, so the compiler
// vectorises them; the border cells keep the checks. Both compute a cell with the same
// operations in the same order.
#include "water_rows.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

// Each row pass is also compiled for AVX2 and picked at load time where the CPU has it:
// eight lanes instead of SSE2's four, and the same IEEE 754 operations (no FMA, so no
// contraction), hence the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define PRISM_WATER_ROW_PASS __attribute__((target_clones("avx2", "default")))
#else
#define PRISM_WATER_ROW_PASS
#endif

namespace prism::water::detail {
namespace {

constexpr float kAvailableFactor = 0.99999904632568359375f;  // 1 - 2^-20 (modules/water/water_grid.glsl)
constexpr float kTan22_5 = 0.41421356f;

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

// Writes cell x of a row: the pair, and the surface and available water the next pass
// reads (restrict members, so the loops that write through it vectorise).
struct RowWriter {
    RowWriter(const WaterRow& out, const float* ground)
        : terrain(ground), hi(out.hi), lo(out.lo), surf(out.surf), avail(out.avail) {}
    void operator()(int x, float h, float l) const {
        hi[x] = h;
        lo[x] = l;
        surf[x] = terrain[x] + h;
        avail[x] = availableWater(h, l);
    }
    const float* __restrict terrain;
    float* __restrict hi;
    float* __restrict lo;
    float* __restrict surf;
    float* __restrict avail;
};

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

template <class T>
const T* rowOf(const Rows3<T>& rows, int dz) {
    return dz < 0 ? rows.north : (dz > 0 ? rows.south : rows.centre);
}

// The flow decision for one cell, with clamped neighbours and a target that may be off the map.
PRISM_WATER_ROW_PASS void flowOutCell(const StepConstants& k, RowAt at, Rows3<float> s, const float* avail,
                                      const float* terrain, float* amountOut, std::int32_t* codeOut, int x) {
    const int W = at.width, H = at.height, z = at.z;
    auto v = [&](int cx, int dz) { return rowOf(s, dz)[std::clamp(cx, 0, W - 1)]; };
    const float nw = v(x - 1, -1), n = v(x, -1), ne = v(x + 1, -1), w = v(x - 1, 0), e = v(x + 1, 0);
    const float sw = v(x - 1, 1), so = v(x, 1), se = v(x + 1, 1);
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
        const float si = s.centre[x];
        const float st = inside ? rowOf(s, oz)[tx] : terrain[x];
        const float fraction = std::min(k.maxFlowFraction, k.flowRateDt * slope);
        const float a = fraction * avail[x];
        const float drop = std::max(0.0f, (si - st) * 0.5f);
        amount = std::min(a, drop);
        code = (oz + 1) * 3 + (ox + 1);
    }
    amountOut[x] = amount;
    codeOut[x] = static_cast<std::int32_t>(code);
}

// Interior cells of an inner row: every target is inside; the same decision as
// flowOutCell(), branch-free, so the loop vectorises.
PRISM_WATER_ROW_PASS void flowOutInterior(const StepConstants& k, int W, Rows3<float> s, const float* avail_,
                                          float* amount_, std::int32_t* code_) {
    const float* __restrict c = s.centre;
    const float* __restrict up = s.north;
    const float* __restrict down = s.south;
    const float* __restrict avail = avail_;
    float* __restrict amountOut = amount_;
    std::int32_t* __restrict codeOut = code_;
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

// One cell with every neighbour checked against the map's edges; returns the water it
// sent off the map.
PRISM_WATER_ROW_PASS float gatherCell(RowAt at, Rows3<float> am, Rows3<std::int32_t> cd, const float* hiIn,
                                      const float* loIn, const float* terrain, const WaterRow& out, int x) {
    const int W = at.width, H = at.height, z = at.z;
    const RowWriter write(out, terrain);
    auto inside = [&](int cx, int cz) { return cx >= 0 && cz >= 0 && cx < W && cz < H; };
    float net = 0.0f, lost = 0.0f;
    const int code = cd.centre[x];
    if (code != 4 && am.centre[x] > 0.0f) {
        net = -am.centre[x];
        if (!inside(x + code % 3 - 1, z + code / 3 - 1)) lost = am.centre[x];
    }
    for (int oz = -1; oz <= 1; ++oz)
        for (int ox = -1; ox <= 1; ++ox) {
            if (ox == 0 && oz == 0) continue;
            const int nx = x + ox, nz = z + oz;
            if (!inside(nx, nz)) continue;
            const int ncode = rowOf(cd, oz)[nx];
            if (ncode != 4 && ncode % 3 - 1 == -ox && ncode / 3 - 1 == -oz) net = net + rowOf(am, oz)[nx];
        }
    float h = hiIn[x], l = loIn[x];
    dfAdd(h, l, net);
    write(x, h, l);
    return lost;
}

// Interior cells of an inner row: every target is inside, nothing is lost. A neighbour at
// (ox, oz) sends here when its code points back: (1 - oz) * 3 + (1 - ox). Adding +0 for a
// neighbour that sends nothing changes no bit: net is never -0 (it starts at +0 or below
// zero, and amounts are >= +0). Branch-free with local restrict pointers, so it vectorises.
PRISM_WATER_ROW_PASS void gatherInterior(int W, Rows3<float> amount, Rows3<std::int32_t> code, const float* hiIn,
                                         const float* loIn, const float* terrain, const WaterRow& out) {
    const float* __restrict am = amount.centre;
    const float* __restrict amN = amount.north;
    const float* __restrict amS = amount.south;
    const std::int32_t* __restrict cd = code.centre;
    const std::int32_t* __restrict cdN = code.north;
    const std::int32_t* __restrict cdS = code.south;
    const float* __restrict hiRow = hiIn;
    const float* __restrict loRow = loIn;
    const RowWriter write(out, terrain);
    const int interiorEnd = W - 1;
    for (int x = 1; x < interiorEnd; ++x) {
        // Every amount is loaded first, so the selects need no conditional loads.
        const float self = am[x], fromNw = amN[x - 1], fromN = amN[x], fromNe = amN[x + 1];
        const float fromW = am[x - 1], fromE = am[x + 1], fromSw = amS[x - 1], fromS = amS[x], fromSe = amS[x + 1];
        float net = ((cd[x] != 4) & (self > 0.0f)) ? -self : 0.0f;
        net = net + (cdN[x - 1] == 8 ? fromNw : 0.0f);
        net = net + (cdN[x] == 7 ? fromN : 0.0f);
        net = net + (cdN[x + 1] == 6 ? fromNe : 0.0f);
        net = net + (cd[x - 1] == 5 ? fromW : 0.0f);
        net = net + (cd[x + 1] == 3 ? fromE : 0.0f);
        net = net + (cdS[x - 1] == 2 ? fromSw : 0.0f);
        net = net + (cdS[x] == 1 ? fromS : 0.0f);
        net = net + (cdS[x + 1] == 0 ? fromSe : 0.0f);
        float h = hiRow[x], l = loRow[x];
        dfAdd(h, l, net);
        write(x, h, l);
    }
}

}  // namespace

PRISM_WATER_ROW_PASS double rainRow(const StepConstants& k, int W, const float* hiIn, const float* loIn,
                                    const float* permeability, const float* terrain, WaterRow out) {
    // What each cell gave up, as (hi, lo) floats: the cell's whole water when emptied,
    // else (capacity, +0); summed below in double, as h + l.
    thread_local std::vector<float> takenHi, takenLo;
    takenHi.resize(static_cast<std::size_t>(W));
    takenLo.resize(static_cast<std::size_t>(W));
    const RowWriter write(out, terrain);
    for (int x = 0; x < W; ++x) {
        float h = hiIn[x], l = loIn[x];
        dfAdd(h, l, k.rainDepth);
        const float capacity = permeability[x] * k.dt;
        float hLeft = h, lLeft = l;
        dfAdd(hLeft, lLeft, -capacity);
        const bool emptied = capacity >= availableWater(h, l);
        takenHi[static_cast<std::size_t>(x)] = emptied ? h : capacity;
        takenLo[static_cast<std::size_t>(x)] = emptied ? l : 0.0f;
        write(x, emptied ? 0.0f : hLeft, emptied ? 0.0f : lLeft);
    }
    // Four running sums over x mod 4, then added: one chain of W dependent double adds
    // cost as much as the rest of the pass. Any order is within rounding of the ledger's
    // single running sum, and this one is the same for every thread count.
    double part[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::size_t x = 0; x < static_cast<std::size_t>(W); ++x)
        part[x & 3] += static_cast<double>(takenHi[x]) + static_cast<double>(takenLo[x]);
    return (part[0] + part[1]) + (part[2] + part[3]);
}

PRISM_WATER_ROW_PASS void flowOutRow(const StepConstants& k, RowAt at, Rows3<float> surf, const float* avail,
                                     const float* terrain, float* amount, std::int32_t* code) {
    const int W = at.width;
    if (at.z == 0 || at.z == at.height - 1 || W < 3) {
        for (int x = 0; x < W; ++x) flowOutCell(k, at, surf, avail, terrain, amount, code, x);
        return;
    }
    flowOutCell(k, at, surf, avail, terrain, amount, code, 0);
    flowOutInterior(k, W, surf, avail, amount, code);
    flowOutCell(k, at, surf, avail, terrain, amount, code, W - 1);
}

PRISM_WATER_ROW_PASS double gatherRow(RowAt at, Rows3<float> amount, Rows3<std::int32_t> code, const float* hiIn,
                                      const float* loIn, const float* terrain, WaterRow out) {
    const int W = at.width;
    double lost = 0.0;
    if (at.z == 0 || at.z == at.height - 1 || W < 3) {
        for (int x = 0; x < W; ++x) lost += gatherCell(at, amount, code, hiIn, loIn, terrain, out, x);
        return lost;
    }
    lost += gatherCell(at, amount, code, hiIn, loIn, terrain, out, 0);
    gatherInterior(W, amount, code, hiIn, loIn, terrain, out);
    lost += gatherCell(at, amount, code, hiIn, loIn, terrain, out, W - 1);
    return lost;
}

PRISM_WATER_ROW_PASS void velocityRow(const StepConstants& k, RowAt at, const float* surf, const float* surfSouth,
                                      const float* avail, const float* availSouth, const float* qEastIn,
                                      const float* qSouthIn, float* qEastOut, float* qSouthOut) {
    const int W = at.width;
    for (int x = 0; x + 1 < W; ++x)
        qEastOut[x] = edgeVelocity(k, qEastIn[x], surf[x], surf[x + 1], avail[x], avail[x + 1]);
    qEastOut[W - 1] = qEastIn[W - 1];
    if (at.z + 1 < at.height) {
        for (int x = 0; x < W; ++x)
            qSouthOut[x] = edgeVelocity(k, qSouthIn[x], surf[x], surfSouth[x], avail[x], availSouth[x]);
    } else {
        std::copy(qSouthIn, qSouthIn + W, qSouthOut);
    }
}

PRISM_WATER_ROW_PASS void applyRow(const StepConstants& k, RowAt at, const float* qEast, const float* qSouth,
                                   const float* qSouthNorth, const float* hiIn, const float* loIn, const float* terrain,
                                   WaterRow out) {
    const int W = at.width, H = at.height, z = at.z;
    const RowWriter write(out, terrain);
    auto cell = [&](int x) {
        const float te = x + 1 < W ? qEast[x] * k.dt : 0.0f;
        const float ts = z + 1 < H ? qSouth[x] * k.dt : 0.0f;
        const float tw = x > 0 ? qEast[x - 1] * k.dt : 0.0f;
        const float tn = z > 0 ? qSouthNorth[x] * k.dt : 0.0f;
        const float net = (tw + tn) - (te + ts);
        float h = hiIn[x], l = loIn[x];
        dfAdd(h, l, net);
        write(x, h, l);
    };
    if (z == 0 || z == H - 1 || W < 3) {
        for (int x = 0; x < W; ++x) cell(x);
        return;
    }
    cell(0);
    // Locals the lambda does not capture (by reference): the trip count and the pointers
    // stay in registers, so the loop vectorises.
    const float* __restrict east = qEast;
    const float* __restrict south = qSouth;
    const float* __restrict north = qSouthNorth;
    const int interiorEnd = W - 1;
    const float dt = k.dt;
    const float* __restrict hiRow = hiIn;
    const float* __restrict loRow = loIn;
    for (int x = 1; x < interiorEnd; ++x) {
        const float net = (east[x - 1] * dt + north[x] * dt) - (east[x] * dt + south[x] * dt);
        float h = hiRow[x], l = loRow[x];
        dfAdd(h, l, net);
        write(x, h, l);
    }
    cell(W - 1);
}

int forwardPairs(int radius) {
    return 2 * radius * (radius + 1);
}

namespace {

// The index of forward offset (dx, dz) among forwardPairs(r): dz = 0, dx = 1..r first, then
// rows dz = 1..r with dx = -r..r.
int forwardIndex(int dx, int dz, int r) {
    return dz == 0 ? dx - 1 : r + (dz - 1) * (2 * r + 1) + (dx + r);
}

}  // namespace

PRISM_WATER_ROW_PASS void smoothPairsRow(const StepConstants& k, RowAt at, const float* const* s, const float* const* a,
                                         float* pairs) {
    const int W = at.width, H = at.height, z = at.z, r = k.smoothRadius;
    const float* __restrict si = s[r];
    const float* __restrict ai = a[r];
    for (int dz = 0; dz <= r && z + dz < H; ++dz)
        for (int dx = dz == 0 ? 1 : -r; dx <= r; ++dx) {
            const float* __restrict sj = s[r + dz];
            const float* __restrict aj = a[r + dz];
            float* __restrict out = pairs + static_cast<std::size_t>(forwardIndex(dx, dz, r)) * W;
            const float weight = k.smoothWeights[static_cast<std::size_t>(dz * 8 + std::abs(dx))];
            const int begin = std::max(0, -dx), end = std::min(W, W - dx);
            for (int x = begin; x < end; ++x) out[x] = smoothExchange(weight, si[x], ai[x], sj[x + dx], aj[x + dx]);
        }
}

// Pairwise exchanges with the (2r+1)^2 neighbours, in the order dz, dx. Inner rows sweep
// each neighbour offset over the row (unit stride, vectorised) and add the pair's exchange:
// row z's own for a forward offset, the neighbour's, negated, for a backward one. The
// two differ only in the sign of a zero (equal surfaces), which changes no sum: net starts
// at +0 and a round-to-nearest sum is -0 only when both terms are.
PRISM_WATER_ROW_PASS void smoothRow(const StepConstants& k, RowAt at, const float* const* s, const float* const* a,
                                    const float* const* pairs, const float* hiIn, const float* loIn,
                                    const float* terrain, WaterRow out, float* netRow) {
    const int W = at.width, H = at.height, z = at.z, r = k.smoothRadius;
    const RowWriter write(out, terrain);
    auto weightOf = [&](int dx, int dz) {
        return k.smoothWeights[static_cast<std::size_t>(std::abs(dz) * 8 + std::abs(dx))];
    };
    auto cell = [&](int x) {
        float net = 0.0f;
        for (int dz = -r; dz <= r; ++dz) {
            if (z + dz < 0 || z + dz >= H) continue;
            for (int dx = -r; dx <= r; ++dx) {
                const int nx = x + dx;
                if ((dx == 0 && dz == 0) || nx < 0 || nx >= W) continue;
                net = net + smoothExchange(weightOf(dx, dz), s[r][x], a[r][x], s[r + dz][nx], a[r + dz][nx]);
            }
        }
        float h = hiIn[x], l = loIn[x];
        dfAdd(h, l, net);
        write(x, h, l);
    };
    if (z < r || z >= H - r || W <= 2 * r) {
        for (int x = 0; x < W; ++x) cell(x);
        return;
    }
    for (int x = 0; x < r; ++x) cell(x);
    // Every offset's term in the per-cell order: a forward one is row z's pair, a backward
    // one the pair of row z + dz seen from its other end, x - x' = -dx, negated (net - p is
    // net + (-1 * p) exactly). Summed four offsets per sweep.
    std::array<const float*, 224> term{};
    std::array<float, 224> sign{};
    int terms = 0;
    for (int dz = -r; dz <= r; ++dz)
        for (int dx = -r; dx <= r; ++dx) {
            if (dx == 0 && dz == 0) continue;
            const bool forward = dz > 0 || (dz == 0 && dx > 0);
            const auto f = static_cast<std::size_t>(forward ? forwardIndex(dx, dz, r) : forwardIndex(-dx, -dz, r));
            term[static_cast<std::size_t>(terms)] = forward ? pairs[r] + f * W : pairs[r + dz] + f * W + dx;
            sign[static_cast<std::size_t>(terms++)] = forward ? 1.0f : -1.0f;
        }
    float* __restrict net = netRow;
    for (int x = r; x < W - r; ++x) net[x] = 0.0f;
    int t = 0;
    for (; t + 4 <= terms; t += 4) {
        const float* __restrict p0 = term[static_cast<std::size_t>(t)];
        const float* __restrict p1 = term[static_cast<std::size_t>(t + 1)];
        const float* __restrict p2 = term[static_cast<std::size_t>(t + 2)];
        const float* __restrict p3 = term[static_cast<std::size_t>(t + 3)];
        const float s0 = sign[static_cast<std::size_t>(t)], s1 = sign[static_cast<std::size_t>(t + 1)];
        const float s2 = sign[static_cast<std::size_t>(t + 2)], s3 = sign[static_cast<std::size_t>(t + 3)];
        for (int x = r; x < W - r; ++x) net[x] = (((net[x] + s0 * p0[x]) + s1 * p1[x]) + s2 * p2[x]) + s3 * p3[x];
    }
    for (; t < terms; ++t) {
        const float* __restrict p = term[static_cast<std::size_t>(t)];
        const float sg = sign[static_cast<std::size_t>(t)];
        for (int x = r; x < W - r; ++x) net[x] = net[x] + sg * p[x];
    }
    for (int x = r; x < W - r; ++x) {
        float h = hiIn[x], l = loIn[x];
        dfAdd(h, l, net[x]);
        write(x, h, l);
    }
    for (int x = W - r; x < W; ++x) cell(x);
}

}  // namespace prism::water::detail
