// Procedural height fields and mean subtraction (see height_field.hpp).
#include "prism/diffraction/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace prism::diffraction {
namespace {

void require(bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
}

void checkGrating(const GratingParams& p) {
    require(std::isfinite(p.periodNm) && p.periodNm > 0.0,
            "period must be > 0 nm (got " + std::to_string(p.periodNm) + ")");
    require(std::isfinite(p.amplitudeNm) && p.amplitudeNm >= 0.0,
            "amplitude must be >= 0 nm (got " + std::to_string(p.amplitudeNm) + ")");
    require(p.periods >= 1 && p.periods <= 4096, "periods must be in 1..4096");
    require(p.samplesPerPeriod >= 4 && p.samplesPerPeriod <= 1024, "samples per period must be in 4..1024");
}

HeightField oneRow(const GratingParams& p) {
    HeightField f;
    f.width = p.periods * p.samplesPerPeriod;
    f.height = 1;
    f.pixelNm = p.periodNm / p.samplesPerPeriod;
    f.heightsNm.resize(static_cast<std::size_t>(f.width));
    return f;
}

void checkPatch(int size, double pixelNm) {
    require(size >= 8 && size <= 4096, "size must be in 8..4096 samples");
    require(std::isfinite(pixelNm) && pixelNm > 0.0, "pixel size must be > 0 nm");
}

}  // namespace

HeightField sinusoidGrating(const GratingParams& p) {
    checkGrating(p);
    HeightField f = oneRow(p);
    for (int x = 0; x < f.width; ++x) {
        const double phase = 2.0 * std::numbers::pi * (x % p.samplesPerPeriod) / p.samplesPerPeriod;
        f.heightsNm[x] = p.amplitudeNm * std::sin(phase);
    }
    return f;
}

HeightField blazedGrating(const GratingParams& p) {
    checkGrating(p);
    HeightField f = oneRow(p);
    for (int x = 0; x < f.width; ++x) {
        f.heightsNm[x] = 2.0 * p.amplitudeNm * (x % p.samplesPerPeriod) / p.samplesPerPeriod;
    }
    return f;
}

HeightField cdTracks(const TrackParams& p) {
    checkPatch(p.size, p.pixelNm);
    require(p.pitchNm > 0.0 && p.pitWidthNm > 0.0 && p.pitWidthNm < p.pitchNm, "need 0 < pit width < pitch");
    require(p.pitDepthNm >= 0.0, "pit depth must be >= 0 nm");
    HeightField f;
    f.width = f.height = p.size;
    f.pixelNm = p.pixelNm;
    f.heightsNm.assign(static_cast<std::size_t>(p.size) * p.size, 0.0);
    std::mt19937 rng(p.seed);
    std::uniform_real_distribution<double> pitLength(900.0, 3300.0);
    const int tracks = std::max(1, static_cast<int>(std::lround(f.widthNm() / p.pitchNm)));
    const double pitch = f.widthNm() / tracks;  // whole tracks, so the tile is periodic
    for (int t = 0; t < tracks; ++t) {
        // Alternate pit / land along the track, lengths drawn from the RNG.
        std::vector<double> edges{0.0};
        while (edges.back() < f.heightNm()) edges.push_back(edges.back() + pitLength(rng));
        const double centre = (t + 0.5) * pitch;
        for (int y = 0; y < f.height; ++y) {
            const double yNm = (y + 0.5) * f.pixelNm;
            const auto it = std::upper_bound(edges.begin(), edges.end(), yNm);
            const bool pit = ((it - edges.begin()) % 2) == 1;
            if (!pit) continue;
            for (int x = 0; x < f.width; ++x) {
                if (std::abs((x + 0.5) * f.pixelNm - centre) <= 0.5 * p.pitWidthNm) {
                    f.heightsNm[static_cast<std::size_t>(y) * f.width + x] = -p.pitDepthNm;
                }
            }
        }
    }
    return f;
}

HeightField snakeRidges(const RidgeParams& p) {
    checkPatch(p.size, p.pixelNm);
    require(p.spacingNm > 0.0 && p.heightNm >= 0.0 && p.wavinessNm >= 0.0,
            "need spacing > 0, height >= 0 and waviness >= 0 nm");
    HeightField f;
    f.width = f.height = p.size;
    f.pixelNm = p.pixelNm;
    f.heightsNm.resize(static_cast<std::size_t>(p.size) * p.size);
    std::mt19937 rng(p.seed);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
    const double twoPi = 2.0 * std::numbers::pi;
    const int ridges = std::max(1, static_cast<int>(std::lround(f.widthNm() / p.spacingNm)));
    // Meander: two sinusoids along y with whole periods over the tile (so it stays periodic).
    const double a1 = phase(rng), a2 = phase(rng), a3 = phase(rng);
    for (int y = 0; y < f.height; ++y) {
        const double v = static_cast<double>(y) / f.height;
        const double shiftNm = p.wavinessNm * (0.7 * std::sin(twoPi * 2 * v + a1) + 0.3 * std::sin(twoPi * 5 * v + a2));
        for (int x = 0; x < f.width; ++x) {
            const double u = ((x + 0.5) * f.pixelNm + shiftNm) / f.widthNm();
            // Spacing jitter: a slow phase modulation of the ridge train (whole cycles per tile).
            const double ridgePhase = twoPi * ridges * u + 0.8 * std::sin(twoPi * u + a3);
            const double c = 0.5 * (1.0 + std::cos(ridgePhase));
            f.heightsNm[static_cast<std::size_t>(y) * f.width + x] = p.heightNm * c * c * c;  // narrow fingers
        }
    }
    return f;
}

void subtractMean(HeightField& field) {
    if (field.heightsNm.empty()) return;
    double sum = 0.0;
    for (double h : field.heightsNm) sum += h;
    const double mean = sum / static_cast<double>(field.heightsNm.size());
    for (double& h : field.heightsNm) h -= mean;
}

double maxAbsHeight(const HeightField& field) {
    double m = 0.0;
    for (double h : field.heightsNm) m = std::max(m, std::abs(h));
    return m;
}

}  // namespace prism::diffraction
