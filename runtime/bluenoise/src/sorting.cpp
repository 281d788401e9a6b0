// Sorting pass (rank matching in blocks) and the application of a retarget permutation.
#include "prism/bluenoise/sorting.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "prism/bluenoise/random.hpp"

namespace prism::bluenoise {

std::vector<std::uint32_t> initialSeeds(int width, int height, std::uint64_t seed) {
    std::vector<std::uint32_t> seeds(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    SplitMix64 rng(seed);
    for (std::uint32_t& s : seeds) s = static_cast<std::uint32_t>(rng.next() >> 32);
    return seeds;
}

void sortSeedsInBlocks(const std::vector<float>& values, const std::vector<std::uint32_t>& target, int width,
                       int height, int blockSize, std::vector<std::uint32_t>& seeds) {
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (width < 1 || height < 1 || values.size() != n || target.size() != n || seeds.size() != n)
        throw std::invalid_argument("sortSeedsInBlocks: values, target and seeds must each hold width*height entries");
    if (blockSize < 1)
        throw std::invalid_argument("sortSeedsInBlocks: block size must be >= 1, got " + std::to_string(blockSize));
    std::vector<int> pixels, byValue, byTarget;
    std::vector<std::uint32_t> old;
    for (int by = 0; by < height; by += blockSize)
        for (int bx = 0; bx < width; bx += blockSize) {
            pixels.clear();
            for (int y = by; y < std::min(by + blockSize, height); ++y)
                for (int x = bx; x < std::min(bx + blockSize, width); ++x) pixels.push_back(y * width + x);
            byValue = pixels;
            byTarget = pixels;
            // NaN values sort last (never compare as smaller), so a broken pixel cannot
            // break the ordering.
            auto valueLess = [&](int a, int b) {
                const float va = values[static_cast<std::size_t>(a)], vb = values[static_cast<std::size_t>(b)];
                const bool na = va != va, nb = vb != vb;
                if (na != nb) return nb;
                if (!na && va != vb) return va < vb;
                return a < b;
            };
            std::sort(byValue.begin(), byValue.end(), valueLess);
            std::sort(byTarget.begin(), byTarget.end(), [&](int a, int b) {
                const std::uint32_t ta = target[static_cast<std::size_t>(a)], tb = target[static_cast<std::size_t>(b)];
                return ta != tb ? ta < tb : a < b;
            });
            old.clear();
            for (int p : pixels) old.push_back(seeds[static_cast<std::size_t>(p)]);
            for (std::size_t k = 0; k < pixels.size(); ++k) {
                const auto from = std::find(pixels.begin(), pixels.end(), byValue[k]) - pixels.begin();
                seeds[static_cast<std::size_t>(byTarget[k])] = old[static_cast<std::size_t>(from)];
            }
        }
}

void applyRetarget(const RetargetPermutation& permutation, int offsetX, int offsetY, int width, int height,
                   std::vector<std::uint32_t>& seeds) {
    const int mw = permutation.width, mh = permutation.height;
    if (mw < 1 || mh < 1 || permutation.source.size() != static_cast<std::size_t>(mw) * static_cast<std::size_t>(mh))
        throw std::invalid_argument("applyRetarget: the permutation is empty or its size does not match");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (seeds.size() != n) throw std::invalid_argument("applyRetarget: seeds must hold width*height entries");
    auto wrap = [](int v, int m) { return ((v % m) + m) % m; };
    auto signedDelta = [](int d, int m) {  // toroidal displacement in (-m/2, m/2]
        d %= m;
        if (d > m / 2) d -= m;
        if (d < -(m - 1) / 2) d += m;
        return d;
    };
    // The largest region of whole mask tiles, as a torus: there the tiled permutation is
    // a bijection (the lift of a permutation of the mask torus); pixels outside keep
    // their seeds.
    const int rw = width / mw * mw, rh = height / mh * mh;
    const std::vector<std::uint32_t> old = seeds;
    for (int y = 0; y < rh; ++y)
        for (int x = 0; x < rw; ++x) {
            const int mx = wrap(x + offsetX, mw), my = wrap(y + offsetY, mh);
            const int src = static_cast<int>(permutation.source[static_cast<std::size_t>(my * mw + mx)]);
            const int sx = wrap(x + signedDelta(src % mw - mx, mw), rw),
                      sy = wrap(y + signedDelta(src / mw - my, mh), rh);
            seeds[static_cast<std::size_t>(y * width + x)] = old[static_cast<std::size_t>(sy * width + sx)];
        }
}

}  // namespace prism::bluenoise
