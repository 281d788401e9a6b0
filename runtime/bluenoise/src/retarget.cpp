// Simulated annealing of the retarget permutation, and its file cache.
#include "prism/bluenoise/retarget.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/random.hpp"
#include "prism/bluenoise/samplers.hpp"
#include "prism/hash/content_hash.hpp"

namespace prism::bluenoise {
namespace {

int wrap(int v, int m) {
    return ((v % m) + m) % m;
}
int torusDistance2(int a, int b, int w, int h) {
    int dx = std::abs(a % w - b % w), dy = std::abs(a / w - b / w);
    dx = std::min(dx, w - dx);
    dy = std::min(dy, h - dy);
    return dx * dx + dy * dy;
}

class Annealer {
  public:
    Annealer(const Mask& mask, const RetargetOptions& o) : o_(o), w_(mask.width), h_(mask.height) {
        const std::size_t n = mask.size();
        value_.resize(n);
        for (std::size_t i = 0; i < n; ++i) value_[i] = (mask.rank[i] + 0.5) / static_cast<double>(n);
        next_.resize(n);
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x)
                next_[static_cast<std::size_t>(y * w_ + x)] =
                    value_[static_cast<std::size_t>(wrap(y + o.shiftY, h_) * w_ + wrap(x + o.shiftX, w_))];
        source_.resize(n);
        for (std::size_t i = 0; i < n; ++i) source_[i] = static_cast<std::uint32_t>(i);
        const int reach = static_cast<int>(std::ceil(3.0 * o.sigmaI));
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx)
                if ((dx || dy) && dx * dx + dy * dy <= reach * reach)
                    pairs_.push_back({dx, dy, std::exp(-(dx * dx + dy * dy) / (o.sigmaI * o.sigmaI))});
        for (int dy = -o.radius; dy <= o.radius; ++dy)
            for (int dx = -o.radius; dx <= o.radius; ++dx)
                if ((dx || dy) && dx * dx + dy * dy < o.radius * o.radius) moves_.push_back({dx, dy});
    }

    double t(int i) const { return value_[source_[static_cast<std::size_t>(i)]]; }

    // Blue energy of pixel i against its window (each pair counted from both ends).
    double blueAt(int i) const {
        const int x = i % w_, y = i / w_;
        double e = 0.0;
        for (const Pair& p : pairs_) {
            const int j = wrap(y + p.dy, h_) * w_ + wrap(x + p.dx, w_);
            if (j == i) continue;
            e += p.weight * std::exp(-std::sqrt(std::abs(t(i) - t(j))) / (o_.sigmaS * o_.sigmaS));
        }
        return e;
    }
    double targetAt(int i) const { return o_.targetWeight * std::abs(t(i) - next_[static_cast<std::size_t>(i)]); }

    double totalBlue() const {
        double e = 0.0;
        for (int i = 0; i < w_ * h_; ++i) e += blueAt(i);
        return e;
    }
    double totalTarget() const {
        double e = 0.0;
        for (int i = 0; i < w_ * h_; ++i) e += targetAt(i);
        return e;
    }

    // Local energy touched by swapping a and b (pairs a-b counted once by the caller's
    // symmetric difference; the doubled count cancels in the delta).
    double local(int a, int b) const { return 2.0 * (blueAt(a) + blueAt(b)) + targetAt(a) + targetAt(b); }

    bool allowed(int a, int b) const {
        const int r2 = o_.radius * o_.radius;
        return torusDistance2(static_cast<int>(source_[static_cast<std::size_t>(b)]), a, w_, h_) < r2 &&
               torusDistance2(static_cast<int>(source_[static_cast<std::size_t>(a)]), b, w_, h_) < r2;
    }
    void swap(int a, int b) { std::swap(source_[static_cast<std::size_t>(a)], source_[static_cast<std::size_t>(b)]); }

    struct Pair {
        int dx, dy;
        double weight;
    };
    struct Move {
        int dx, dy;
    };
    const RetargetOptions& o_;
    int w_, h_;
    std::vector<double> value_, next_;
    std::vector<std::uint32_t> source_;
    std::vector<Pair> pairs_;
    std::vector<Move> moves_;
};

double temperature(const RetargetOptions& o, double t0, double epoch) {
    switch (o.schedule) {
        case CoolingSchedule::Hajek: return t0 * std::log(2.0) / std::log(2.0 + epoch);
        case CoolingSchedule::Linear: return std::max(0.0, t0 * (1.0 - epoch / o.epochs));
        case CoolingSchedule::Exponential: return t0 * std::pow(o.alpha, epoch);
        case CoolingSchedule::Inverse: return t0 / (1.0 + o.alpha * epoch);
    }
    return 0.0;
}

void validate(const Mask& mask, const RetargetOptions& o) {
    if (mask.size() < 2) throw std::invalid_argument("retarget: the mask needs at least 2 pixels");
    // Moves go to pixels closer than the radius: radius 1 would allow none.
    if (o.radius < 2 || o.radius > 64)
        throw std::invalid_argument("retarget: radius must be 2..64, got " + std::to_string(o.radius));
    if (!(o.sigmaI > 0) || !(o.sigmaS > 0) || !std::isfinite(o.sigmaI) || !std::isfinite(o.sigmaS))
        throw std::invalid_argument("retarget: sigma_i and sigma_s must be finite and > 0");
    if (o.epochs < 0 || o.epochs > 100000) throw std::invalid_argument("retarget: epochs must be 0..100000");
    if (!(o.alpha > 0) || !std::isfinite(o.alpha))
        throw std::invalid_argument("retarget: alpha must be finite and > 0");
    if (!(o.targetWeight >= 0) || !std::isfinite(o.targetWeight))
        throw std::invalid_argument("retarget: target weight must be >= 0");
}

std::string cacheKey(const Mask& mask, const RetargetOptions& o) {
    const std::uint64_t hash =
        hash::hash64({reinterpret_cast<const char*>(mask.rank.data()), mask.rank.size() * sizeof(std::uint32_t)});
    std::ostringstream key;
    key.precision(17);
    key << "prism-bluenoise-retarget 1 " << mask.width << "x" << mask.height << " mask " << hash << " radius "
        << o.radius << " sigma_i " << o.sigmaI << " sigma_s " << o.sigmaS << " weight " << o.targetWeight
        << " schedule " << coolingScheduleName(o.schedule) << " alpha " << o.alpha << " epochs " << o.epochs << " seed "
        << o.seed << " shift " << o.shiftX << " " << o.shiftY << "\n";
    return key.str();
}

}  // namespace

CoolingSchedule parseCoolingSchedule(const std::string& name) {
    if (name == "hajek") return CoolingSchedule::Hajek;
    if (name == "linear") return CoolingSchedule::Linear;
    if (name == "exponential") return CoolingSchedule::Exponential;
    if (name == "inverse") return CoolingSchedule::Inverse;
    throw std::invalid_argument("unknown cooling schedule '" + name + "' (hajek, linear, exponential or inverse)");
}

const char* coolingScheduleName(CoolingSchedule s) {
    switch (s) {
        case CoolingSchedule::Hajek: return "hajek";
        case CoolingSchedule::Linear: return "linear";
        case CoolingSchedule::Exponential: return "exponential";
        case CoolingSchedule::Inverse: return "inverse";
    }
    return "?";
}

void frameShift(int width, int height, int& shiftX, int& shiftY) {
    std::uint32_t dx = 0, dy = 0;
    r2Offset(1, width, height, dx, dy);
    shiftX = static_cast<int>(dx);
    shiftY = static_cast<int>(dy);
}

RetargetResult computeRetarget(const Mask& mask, const RetargetOptions& options) {
    validate(mask, options);
    Annealer a(mask, options);
    const int n = static_cast<int>(mask.size());
    SplitMix64 rng(options.seed);
    RetargetResult result;
    const double blue0 = a.totalBlue();
    result.initialTarget = a.totalTarget();
    result.initialEnergy = blue0 + result.initialTarget;

    auto proposal = [&](int& i, int& j) {
        i = static_cast<int>(rng.below(static_cast<std::uint64_t>(n)));
        const Annealer::Move m = a.moves_[static_cast<std::size_t>(rng.below(a.moves_.size()))];
        j = wrap(i / a.w_ + m.dy, a.h_) * a.w_ + wrap(i % a.w_ + m.dx, a.w_);
        return i != j && a.allowed(i, j);
    };
    auto delta = [&](int i, int j) {
        const double before = a.local(i, j);
        a.swap(i, j);
        const double after = a.local(i, j);
        a.swap(i, j);
        return after - before;
    };
    // Start temperature: accept ~90% of uphill moves at first.
    double uphill = 0.0;
    int samples = 0;
    for (int k = 0; k < 200; ++k) {
        int i = 0, j = 0;
        if (!proposal(i, j)) continue;
        const double d = delta(i, j);
        if (d > 0) uphill += d, ++samples;
    }
    const double t0 = samples > 0 ? -(uphill / samples) / std::log(0.9) : 1.0;

    const std::uint64_t total = static_cast<std::uint64_t>(options.epochs) * static_cast<std::uint64_t>(n);
    for (std::uint64_t move = 0; move < total; ++move) {
        int i = 0, j = 0;
        if (!proposal(i, j)) continue;
        ++result.moves;
        const double temp = temperature(options, t0, static_cast<double>(move) / n);
        const double d = delta(i, j);
        if (d < 0 || (temp > 0 && rng.uniform() < std::exp(-d / temp))) {
            a.swap(i, j);
            ++result.accepted;
        }
    }
    result.finalTarget = a.totalTarget();
    result.finalEnergy = a.totalBlue() + result.finalTarget;
    result.permutation = {mask.width, mask.height, a.source_};
    return result;
}

RetargetPermutation loadOrComputeRetarget(const Mask& mask, const RetargetOptions& options,
                                          const std::filesystem::path& cache, bool* fromCache) {
    const std::string key = cacheKey(mask, options);
    {
        std::ifstream in(cache, std::ios::binary);
        if (in) {
            std::string header;
            std::getline(in, header);
            header += '\n';
            if (header == key) {
                RetargetPermutation p{mask.width, mask.height, std::vector<std::uint32_t>(mask.size())};
                in.read(reinterpret_cast<char*>(p.source.data()), static_cast<std::streamsize>(p.source.size() * 4));
                bool valid = static_cast<bool>(in);
                std::vector<char> seen(p.source.size(), 0);
                for (std::uint32_t s : p.source) {
                    if (s >= p.source.size() || seen[s]) {
                        valid = false;
                        break;
                    }
                    seen[s] = 1;
                }
                if (valid) {
                    if (fromCache) *fromCache = true;
                    return p;
                }
            }
        }
    }
    RetargetPermutation p = computeRetarget(mask, options).permutation;
    std::string bytes = key;
    bytes.append(reinterpret_cast<const char*>(p.source.data()), p.source.size() * 4);
    writeFileAtomically(cache, bytes);
    if (fromCache) *fromCache = false;
    return p;
}

}  // namespace prism::bluenoise
