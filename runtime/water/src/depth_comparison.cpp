// Resampling of water maps onto a common grid and their comparison (depth_comparison.hpp).
#include "prism/water/depth_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace prism::water {
namespace {

// The target node whose cell holds source node j: round(j (to - 1) / (from - 1)), halves
// up, in integers so that no rounding of a product decides a tie.
int targetOf(int j, int from, int to) {
    return static_cast<int>((2LL * j * (to - 1) + (from - 1)) / (2LL * (from - 1)));
}

}  // namespace

std::vector<float> resampleDepth(std::span<const float> depth, int width, int height, int toWidth, int toHeight) {
    if (width < 2 || height < 2 || toWidth < 2 || toHeight < 2 || toWidth > width || toHeight > height ||
        depth.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
        throw std::invalid_argument("resampleDepth: needs " + std::to_string(width) + " x " + std::to_string(height) +
                                    " values at least 2 x 2 and at least as fine as the " + std::to_string(toWidth) +
                                    " x " + std::to_string(toHeight) + " target (itself at least 2 x 2)");
    const std::size_t n = static_cast<std::size_t>(toWidth) * static_cast<std::size_t>(toHeight);
    std::vector<double> sum(n, 0.0);
    std::vector<int> count(n, 0);
    for (int z = 0; z < height; ++z) {
        const std::size_t row = static_cast<std::size_t>(targetOf(z, height, toHeight)) * toWidth;
        for (int x = 0; x < width; ++x) {
            const std::size_t t = row + static_cast<std::size_t>(targetOf(x, width, toWidth));
            sum[t] += depth[static_cast<std::size_t>(z) * width + static_cast<std::size_t>(x)];
            ++count[t];
        }
    }
    std::vector<float> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<float>(sum[i] / count[i]);
    return out;
}

double DepthComparison::wettedAreaError() const {
    if (referenceWettedShare == 0.0) return wettedShare == 0.0 ? 0.0 : INFINITY;
    return std::abs(wettedShare - referenceWettedShare) / referenceWettedShare;
}

DepthComparison compareDepth(std::span<const float> depth, std::span<const float> reference, double wetDepth) {
    if (depth.size() != reference.size() || depth.empty())
        throw std::invalid_argument("compareDepth: " + std::to_string(depth.size()) + " depths against " +
                                    std::to_string(reference.size()) + " reference depths; resample to one grid first");
    std::vector<double> diff(depth.size());
    DepthComparison c;
    double sum = 0.0;
    std::size_t wet = 0, referenceWet = 0;
    for (std::size_t i = 0; i < depth.size(); ++i) {
        diff[i] = std::abs(static_cast<double>(depth[i]) - static_cast<double>(reference[i])) * 1e3;
        sum += diff[i];
        wet += depth[i] > wetDepth;
        referenceWet += reference[i] > wetDepth;
    }
    const double n = static_cast<double>(depth.size());
    c.meanAbsMm = sum / n;
    const std::size_t k = std::min(diff.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * n)) - 1);
    std::nth_element(diff.begin(), diff.begin() + static_cast<std::ptrdiff_t>(k), diff.end());
    c.p95AbsMm = diff[k];
    c.wettedShare = static_cast<double>(wet) / n;
    c.referenceWettedShare = static_cast<double>(referenceWet) / n;
    return c;
}

}  // namespace prism::water
