// Void-and-cluster (Ulichney 1993) with incremental toroidal Gaussian energies.
#include "prism/bluenoise/void_and_cluster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "prism/bluenoise/random.hpp"

namespace prism::bluenoise {
namespace {

// Energies of every pixel from the "on" pixels, with per-row search caches. With depth
// d > 1 the pixels are voxels of d slices (index = (t * height + y) * width + x), and two
// voxels interact within a slice (spatial Gaussian) or at the same pixel across slices
// (temporal Gaussian, toroidal in t), as in spatiotemporal blue noise (Wolfe et al. 2022).
class EnergyField {
  public:
    EnergyField(int width, int height, double sigma, int depth = 1, double sigmaTime = 1.0)
        : w_(width), h_(height), d_(depth) {
        // Cut the kernel where exp(-d^2 / (2 sigma^2)) < 1e-6, and never wider than the torus.
        const int reach = static_cast<int>(std::ceil(sigma * std::sqrt(2.0 * std::log(1e6))));
        x0_ = -std::min(reach, (w_ - 1) / 2);
        x1_ = std::min(reach, w_ / 2);
        y0_ = -std::min(reach, (h_ - 1) / 2);
        y1_ = std::min(reach, h_ / 2);
        kw_ = x1_ - x0_ + 1;
        const double twoSigma2 = 2.0 * sigma * sigma;
        for (int dy = y0_; dy <= y1_; ++dy)
            for (int dx = x0_; dx <= x1_; ++dx) kernel_.push_back(std::exp(-(dx * dx + dy * dy) / twoSigma2));
        const int reachTime = static_cast<int>(std::ceil(sigmaTime * std::sqrt(2.0 * std::log(1e6))));
        t0_ = -std::min(reachTime, (d_ - 1) / 2);
        t1_ = std::min(reachTime, d_ / 2);
        for (int dt = t0_; dt <= t1_; ++dt) timeKernel_.push_back(std::exp(-(dt * dt) / (2.0 * sigmaTime * sigmaTime)));
        rows_ = h_ * d_;
        const std::size_t n = static_cast<std::size_t>(w_) * static_cast<std::size_t>(rows_);
        energy_.assign(n, 0.0);
        on_.assign(n, 0);
        dirtyVoid_.assign(static_cast<std::size_t>(rows_), 1);
        dirtyCluster_.assign(static_cast<std::size_t>(rows_), 1);
        rowVoid_.assign(static_cast<std::size_t>(rows_), -1);
        rowCluster_.assign(static_cast<std::size_t>(rows_), -1);
        cols_.resize(static_cast<std::size_t>(kw_));
    }

    bool isOn(int i) const { return on_[static_cast<std::size_t>(i)] != 0; }

    void set(int index, bool on) {
        if (isOn(index) == on) return;
        on_[static_cast<std::size_t>(index)] = on ? 1 : 0;
        const double sign = on ? 1.0 : -1.0;
        const int x = index % w_, y = (index / w_) % h_, t = index / w_ / h_;
        for (int k = 0; k < kw_; ++k) cols_[static_cast<std::size_t>(k)] = wrap(x + x0_ + k, w_);
        std::size_t kernelIndex = 0;
        for (int dt = t0_; dt <= t1_; ++dt) {  // the same pixel in the other slices
            if (dt == 0) continue;
            const std::size_t r = static_cast<std::size_t>(wrap(t + dt, d_) * h_ + y);
            markDirty(r, x, on);
            energy_[r * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x)] +=
                sign * timeKernel_[static_cast<std::size_t>(dt - t0_)];
        }
        for (int dy = y0_; dy <= y1_; ++dy) {
            const int row = t * h_ + wrap(y + dy, h_);
            const std::size_t r = static_cast<std::size_t>(row);
            markDirty(r, x, on);
            double* line = energy_.data() + r * static_cast<std::size_t>(w_);
            for (int k = 0; k < kw_; ++k) line[cols_[static_cast<std::size_t>(k)]] += sign * kernel_[kernelIndex++];
        }
        const std::size_t r = static_cast<std::size_t>(index / w_);
        if (on && rowVoid_[r] == index) dirtyVoid_[r] = 1;
        if (!on && rowCluster_[r] == index) dirtyCluster_[r] = 1;
    }

    // The "off" pixel of lowest energy (largest void); -1 when every pixel is on.
    int largestVoid() {
        refreshVoids();
        int best = -1;
        for (int y = 0; y < rows_; ++y) {
            const int c = rowVoid_[static_cast<std::size_t>(y)];
            if (c >= 0 && (best < 0 || energy_[static_cast<std::size_t>(c)] < energy_[static_cast<std::size_t>(best)]))
                best = c;
        }
        return best;
    }

    // The "on" pixel of highest energy (tightest cluster); -1 when none is on.
    int tightestCluster() {
        refreshClusters();
        int best = -1;
        for (int y = 0; y < rows_; ++y) {
            const int c = rowCluster_[static_cast<std::size_t>(y)];
            if (c >= 0 && (best < 0 || energy_[static_cast<std::size_t>(c)] > energy_[static_cast<std::size_t>(best)]))
                best = c;
        }
        return best;
    }

  private:
    static int wrap(int v, int n) { return ((v % n) + n) % n; }

    // Adding raises energies: a row's lowest zero stays lowest unless it lies in the window
    // (or was just turned on); removing lowers them, likewise for the highest one.
    void markDirty(std::size_t r, int x, bool on) {
        if (on) {
            dirtyCluster_[r] = 1;
            if (inWindow(rowVoid_[r], x)) dirtyVoid_[r] = 1;
        } else {
            dirtyVoid_[r] = 1;
            if (inWindow(rowCluster_[r], x)) dirtyCluster_[r] = 1;
        }
    }

    // Is pixel `index` (or -1) in the kernel window's columns around column x?
    bool inWindow(int index, int x) const {
        if (index < 0) return true;
        return wrap(index % w_ - x - x0_, w_) < kw_;
    }

    void refreshVoids() {
        for (int y = 0; y < rows_; ++y) {
            if (!dirtyVoid_[static_cast<std::size_t>(y)]) continue;
            dirtyVoid_[static_cast<std::size_t>(y)] = 0;
            int best = -1;
            for (int i = y * w_; i < (y + 1) * w_; ++i)
                if (!isOn(i) &&
                    (best < 0 || energy_[static_cast<std::size_t>(i)] < energy_[static_cast<std::size_t>(best)]))
                    best = i;
            rowVoid_[static_cast<std::size_t>(y)] = best;
        }
    }

    void refreshClusters() {
        for (int y = 0; y < rows_; ++y) {
            if (!dirtyCluster_[static_cast<std::size_t>(y)]) continue;
            dirtyCluster_[static_cast<std::size_t>(y)] = 0;
            int best = -1;
            for (int i = y * w_; i < (y + 1) * w_; ++i)
                if (isOn(i) &&
                    (best < 0 || energy_[static_cast<std::size_t>(i)] > energy_[static_cast<std::size_t>(best)]))
                    best = i;
            rowCluster_[static_cast<std::size_t>(y)] = best;
        }
    }

    int w_, h_, d_, rows_ = 0;
    int x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0, t0_ = 0, t1_ = 0, kw_ = 1;
    std::vector<double> kernel_, timeKernel_;
    std::vector<double> energy_;
    std::vector<unsigned char> on_;
    std::vector<unsigned char> dirtyVoid_, dirtyCluster_;
    std::vector<int> rowVoid_, rowCluster_;
    std::vector<int> cols_;
};

void validate(const VoidAndClusterOptions& o) {
    auto side = [](const char* name, int v) {
        if (v < 1 || v > kMaxMaskSide)
            throw std::invalid_argument(std::string("void-and-cluster: ") + name + " must be 1.." +
                                        std::to_string(kMaxMaskSide) + ", got " + std::to_string(v));
    };
    side("width", o.width);
    side("height", o.height);
    if (!std::isfinite(o.sigma) || o.sigma <= 0.0)
        throw std::invalid_argument("void-and-cluster: sigma must be a finite number > 0, got " +
                                    std::to_string(o.sigma));
    if (!std::isfinite(o.initialFraction) || o.initialFraction <= 0.0 || o.initialFraction > 0.5)
        throw std::invalid_argument("void-and-cluster: initialFraction must be in (0, 0.5], got " +
                                    std::to_string(o.initialFraction));
}

}  // namespace

namespace {

// Void-and-cluster ranks 0..n-1 of the w*h*depth voxels.
std::vector<std::uint32_t> voidAndClusterRanks(const VoidAndClusterOptions& options, int depth, double sigmaTime) {
    const int n = options.width * options.height * depth;
    std::vector<std::uint32_t> rank(static_cast<std::size_t>(n), 0);
    if (n == 1) return rank;

    // Initial binary pattern: a seeded random subset (partial Fisher-Yates shuffle).
    const int ones = std::max(1, static_cast<int>(options.initialFraction * n));
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
    SplitMix64 rng(options.seed);
    for (int i = 0; i < ones; ++i) {
        const int j = i + static_cast<int>(rng.below(static_cast<std::uint64_t>(n - i)));
        std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
    }
    EnergyField field(options.width, options.height, options.sigma, depth, sigmaTime);
    for (int i = 0; i < ones; ++i) field.set(order[static_cast<std::size_t>(i)], true);

    // Relax: move the tightest cluster into the largest void until that changes nothing.
    for (int iteration = 0; iteration < n; ++iteration) {
        const int cluster = field.tightestCluster();
        field.set(cluster, false);
        const int voidIndex = field.largestVoid();
        field.set(voidIndex, true);
        if (voidIndex == cluster) break;
    }
    // Phase 1: remove tightest clusters from a copy of the prototype, ranks ones-1 .. 0.
    {
        EnergyField copy = field;
        for (int r = ones - 1; r >= 0; --r) {
            const int cluster = copy.tightestCluster();
            copy.set(cluster, false);
            rank[static_cast<std::size_t>(cluster)] = static_cast<std::uint32_t>(r);
        }
    }
    // Phases 2 and 3: fill the largest voids, ranks ones .. n-1. (Phase 3's "tightest
    // cluster of zeros" is the lowest-energy zero on a torus, since every pixel's
    // window sums to the same total: the same search.)
    for (int r = ones; r < n; ++r) {
        const int voidIndex = field.largestVoid();
        field.set(voidIndex, true);
        rank[static_cast<std::size_t>(voidIndex)] = static_cast<std::uint32_t>(r);
    }
    return rank;
}

}  // namespace

Mask generateVoidAndCluster(const VoidAndClusterOptions& options) {
    validate(options);
    return Mask{options.width, options.height, voidAndClusterRanks(options, 1, 1.0)};
}

std::vector<Mask> generateSpatiotemporal(const VoidAndClusterOptions& options, int depth, double sigmaTime) {
    validate(options);
    if (depth < 1 || depth > kMaxMaskDepth)
        throw std::invalid_argument("spatiotemporal void-and-cluster: depth must be 1.." +
                                    std::to_string(kMaxMaskDepth) + ", got " + std::to_string(depth));
    if (!std::isfinite(sigmaTime) || sigmaTime <= 0.0)
        throw std::invalid_argument("spatiotemporal void-and-cluster: sigmaTime must be a finite number > 0, got " +
                                    std::to_string(sigmaTime));
    const std::size_t n = static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
    const std::vector<std::uint32_t> ranks = voidAndClusterRanks(options, depth, sigmaTime);
    // Each slice: its voxels in the order of their volume ranks, ranked 0..N-1.
    std::vector<Mask> slices;
    std::vector<std::size_t> order(n);
    for (int t = 0; t < depth; ++t) {
        const std::size_t base = static_cast<std::size_t>(t) * n;
        for (std::size_t i = 0; i < n; ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return ranks[base + a] < ranks[base + b]; });
        Mask slice{options.width, options.height, std::vector<std::uint32_t>(n)};
        for (std::size_t k = 0; k < n; ++k) slice.rank[order[k]] = static_cast<std::uint32_t>(k);
        slices.push_back(std::move(slice));
    }
    return slices;
}

}  // namespace prism::bluenoise
