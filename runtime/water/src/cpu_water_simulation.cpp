// The CPU water step, fused. A substep's passes (water_rows.hpp: rain and infiltration,
// flow out, gather, edge velocities, apply, smoothing) run one after the other on each
// row as soon as the rows it reads are done, so the intermediate water lives in small
// per-thread rings of rows that stay in cache, and a substep streams only its state:
// depth pairs, edge velocities, terrain and permeability in, depth pairs and edge
// velocities out. The grid is split into row bands on threads (row_bands.hpp) with one
// barrier per substep; a band also computes the few rows of the earlier passes on either
// side that its later passes read (a halo of smoothing radius + 3 rows), into its rings,
// never into shared arrays. Every cell is computed with the same operations in the same
// order as by the per-pass step (tests/water/reference_water_step.cpp), so the thread
// count, the band split and the fusion change no bit of the water.
#include <algorithm>
#include <array>
#include <cstring>
#include <functional>

#include "prism/water/water_simulation.hpp"
#include "row_bands.hpp"
#include "water_rows.hpp"

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64)
#include <xmmintrin.h>
#define PRISM_WATER_HAVE_MXCSR 1
#endif

namespace prism::water {
namespace {

using detail::RowAt;
using detail::Rows3;
using detail::WaterRow;

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

// The arrays of the state a substep reads and writes.
struct StepArrays {
    const float *hi, *lo, *qEast, *qSouth, *terrain, *permeability;
    float *hiNext, *loNext, *qEastNext, *qSouthNext;
    double *infiltratedRow, *lostRow;
};

// Rows [begin, end) of the grid that one pass computes for a band.
struct Span {
    int begin, end;
    bool has(int z) const { return z >= begin && z < end; }
};

// The intermediate rows of one thread: the water after rain, the flow amounts and codes,
// the water after the gather, the edge velocities of halo rows, the water after the
// distribution (2r + 1 rows, what the smoothing reads), the smoothing's pair exchanges
// (r + 1 rows of 2r (r + 1) offsets), and scratch rows. A ring row is reused once no later
// pass reads it (see FusedBand::run for the lags).
class Rings {
  public:
    static constexpr int kShort = 4;
    void fit(int width, int radius) {
        width_ = width;
        applied_ = 2 * radius + 1;
        pairSlots_ = radius + 1;
        pairRows_ = detail::forwardPairs(radius);
        const std::size_t w = static_cast<std::size_t>(width);
        floats_.resize(w * static_cast<std::size_t>(pairsFirst() + pairSlots_ * pairRows_));
        codes_.resize(w * kShort);
    }
    WaterRow rain(int z) { return water(0, kShort, z); }
    float* amount(int z) { return row(kShort * 4, kShort, z); }
    std::int32_t* code(int z) { return codes_.data() + static_cast<std::size_t>(z % kShort) * width(); }
    WaterRow gathered(int z) { return water(kShort * 5, kShort, z); }
    float* qEast(int z) { return row(kShort * 9, kShort, z); }
    float* qSouth(int z) { return row(kShort * 10, kShort, z); }
    WaterRow applied(int z) { return water(kShort * 11, applied_, z); }
    // Where the last pass puts the surface and available water nobody reads, and the
    // smoothing's sums.
    float* scratch(int i) { return row(kShort * 11 + applied_ * 4 + i, 1, 0); }
    float* pairs(int z) { return row(pairsFirst() + (z % pairSlots_) * pairRows_, 1, 0); }

  private:
    int pairsFirst() const { return kShort * 11 + applied_ * 4 + 3; }
    std::size_t width() const { return static_cast<std::size_t>(width_); }
    float* row(int first, int slots, int z) {
        return floats_.data() + static_cast<std::size_t>(first + z % slots) * width();
    }
    WaterRow water(int first, int slots, int z) {
        return {row(first, slots, z), row(first + slots, slots, z), row(first + 2 * slots, slots, z),
                row(first + 3 * slots, slots, z)};
    }
    int width_ = 0, applied_ = 1, pairSlots_ = 1, pairRows_ = 0;
    std::vector<float> floats_;
    std::vector<std::int32_t> codes_;
};

// One band's part of a substep: its own rows [z0, z1) of the new state, and the halo rows
// of the earlier passes that those read, each pass a method.
class FusedBand {
  public:
    FusedBand(const StepConstants& k, const StepArrays& g, int width, int height, int z0, int z1, Rings& rings)
        : k_(k), g_(g), W_(width), H_(height), r_(k.smoothRadius), own_{z0, z1}, ring_(rings) {
        smooth_ = own_;
        pairs_ = widen(own_, r_, 0);
        apply_ = r_ > 0 ? widen(own_, r_, r_) : own_;
        velocity_ = widen(apply_, 1, 0);
        gather_ = widen(velocity_, 0, 1);
        flowOut_ = widen(gather_, 1, 1);
        rain_ = widen(flowOut_, 1, 1);
        ring_.fit(width, r_);
    }

    // Pass p on row y - lag(p): every row a pass reads was computed on an earlier
    // iteration or earlier in this one (flow out reads rain rows z +- 1, the gather flow
    // rows z +- 1, velocities gathered rows z and z + 1, apply velocities z - 1 and z,
    // pair exchanges applied rows z .. z + r, smoothing applied rows z +- r and pair rows
    // z - r .. z), and no ring row is overwritten while still read.
    void run() {
        const int lastRow = own_.end - 1 + 3 + r_;
        for (int y = rain_.begin; y <= lastRow; ++y) {
            if (rain_.has(y)) rain(y);
            if (flowOut_.has(y - 1)) flowOut(y - 1);
            if (gather_.has(y - 2)) gather(y - 2);
            if (velocity_.has(y - 3)) velocity(y - 3);
            if (apply_.has(y - 3)) apply(y - 3);
            if (r_ > 0 && pairs_.has(y - 3 - r_)) pairs(y - 3 - r_);
            if (r_ > 0 && smooth_.has(y - 3 - r_)) smooth(y - 3 - r_);
        }
    }

  private:
    Span widen(Span s, int up, int down) const { return {std::max(0, s.begin - up), std::min(H_, s.end + down)}; }
    int clampRow(int z) const { return std::clamp(z, 0, H_ - 1); }
    std::size_t at(int z) const { return static_cast<std::size_t>(z) * static_cast<std::size_t>(W_); }
    RowAt rowAt(int z) const { return {W_, H_, z}; }
    // The new state of an own row, with scratch for what nobody reads.
    WaterRow final(int z) { return {g_.hiNext + at(z), g_.loNext + at(z), ring_.scratch(0), ring_.scratch(1)}; }
    float* qEastOf(int z) { return own_.has(z) ? g_.qEastNext + at(z) : ring_.qEast(z); }
    float* qSouthOf(int z) { return own_.has(z) ? g_.qSouthNext + at(z) : ring_.qSouth(z); }

    void rain(int z) {
        const double infiltrated = detail::rainRow(k_, W_, g_.hi + at(z), g_.lo + at(z), g_.permeability + at(z),
                                                   g_.terrain + at(z), ring_.rain(z));
        if (own_.has(z)) g_.infiltratedRow[z] = infiltrated;
    }
    void flowOut(int z) {
        const Rows3<float> surf{ring_.rain(clampRow(z - 1)).surf, ring_.rain(z).surf, ring_.rain(clampRow(z + 1)).surf};
        detail::flowOutRow(k_, rowAt(z), surf, ring_.rain(z).avail, g_.terrain + at(z), ring_.amount(z), ring_.code(z));
    }
    void gather(int z) {
        const int n = clampRow(z - 1), s = clampRow(z + 1);
        const Rows3<float> amount{ring_.amount(n), ring_.amount(z), ring_.amount(s)};
        const Rows3<std::int32_t> code{ring_.code(n), ring_.code(z), ring_.code(s)};
        const WaterRow in = ring_.rain(z);
        const double lost =
            detail::gatherRow(rowAt(z), amount, code, in.hi, in.lo, g_.terrain + at(z), ring_.gathered(z));
        if (own_.has(z)) g_.lostRow[z] = lost;
    }
    void velocity(int z) {
        const WaterRow here = ring_.gathered(z), south = ring_.gathered(clampRow(z + 1));
        detail::velocityRow(k_, rowAt(z), here.surf, south.surf, here.avail, south.avail, g_.qEast + at(z),
                            g_.qSouth + at(z), qEastOf(z), qSouthOf(z));
    }
    void apply(int z) {
        const WaterRow in = ring_.gathered(z);
        const WaterRow out = r_ == 0 ? final(z) : ring_.applied(z);
        detail::applyRow(k_, rowAt(z), qEastOf(z), qSouthOf(z), z > 0 ? qSouthOf(z - 1) : nullptr, in.hi, in.lo,
                         g_.terrain + at(z), out);
    }
    // Rows z + dz of the water after the distribution, for |dz| <= r (null off the grid).
    void neighbourRows(int z, std::array<const float*, 15>& surf, std::array<const float*, 15>& avail) {
        for (int dz = -r_; dz <= r_; ++dz)
            if (z + dz >= 0 && z + dz < H_) {
                surf[static_cast<std::size_t>(r_ + dz)] = ring_.applied(z + dz).surf;
                avail[static_cast<std::size_t>(r_ + dz)] = ring_.applied(z + dz).avail;
            }
    }
    void pairs(int z) {
        std::array<const float*, 15> surf{}, avail{};
        neighbourRows(z, surf, avail);
        detail::smoothPairsRow(k_, rowAt(z), surf.data(), avail.data(), ring_.pairs(z));
    }
    void smooth(int z) {
        std::array<const float*, 15> surf{}, avail{};
        std::array<const float*, 8> pairs{};
        neighbourRows(z, surf, avail);
        for (int dz = -r_; dz <= 0; ++dz)
            if (z + dz >= 0) pairs[static_cast<std::size_t>(r_ + dz)] = ring_.pairs(z + dz);
        const WaterRow in = ring_.applied(z);
        detail::smoothRow(k_, rowAt(z), surf.data(), avail.data(), pairs.data(), in.hi, in.lo, g_.terrain + at(z),
                          final(z), ring_.scratch(2));
    }

    const StepConstants& k_;
    const StepArrays& g_;
    const int W_, H_, r_;
    const Span own_;
    Span smooth_{}, pairs_{}, apply_{}, velocity_{}, gather_{}, flowOut_{}, rain_{};
    Rings& ring_;
};

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
    hiNext_.assign(n, 0.0f);
    loNext_.assign(n, 0.0f);
    qEast_.assign(n, 0.0f);
    qSouth_.assign(n, 0.0f);
    qEastNext_.assign(n, 0.0f);
    qSouthNext_.assign(n, 0.0f);
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

int CpuWaterSimulation::bytesStreamedPerCellPerSubstep() {
    // hi, lo, q east, q south, terrain, permeability read; hi, lo, q east, q south written.
    return 6 * 4 + 4 * 4;
}

void CpuWaterSimulation::runSubsteps(const StepConstants& k, long count) {
    FlushDenormals ftz;
    for (long s = 0; s < count; ++s) substep(k);
}

void CpuWaterSimulation::substep(const StepConstants& k) {
    const int W = width(), H = height();
    const StepArrays arrays{hi_.data(),
                            lo_.data(),
                            qEast_.data(),
                            qSouth_.data(),
                            terrain_.heights.data(),
                            permeability_.data(),
                            hiNext_.data(),
                            loNext_.data(),
                            qEastNext_.data(),
                            qSouthNext_.data(),
                            infiltratedRow_.data(),
                            lostRow_.data()};
    const std::function<void(int, int)> band = [&](int z0, int z1) {
        thread_local Rings rings;
        FusedBand(k, arrays, W, H, z0, z1, rings).run();
    };
    if (bands_)
        bands_->run(H, band);
    else
        band(0, H);
    hi_.swap(hiNext_);
    lo_.swap(loNext_);
    qEast_.swap(qEastNext_);
    qSouth_.swap(qSouthNext_);
    double inf = 0.0, lost = 0.0;
    for (int z = 0; z < H; ++z) {
        inf += infiltratedRow_[static_cast<std::size_t>(z)];
        lost += lostRow_[static_cast<std::size_t>(z)];
    }
    infiltrated_ += inf;
    lost_ += lost;
}

}  // namespace prism::water
