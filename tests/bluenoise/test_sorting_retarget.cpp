// Sorting and retargeting: seeds stay a permutation in every block (sorting) and on the
// screen (retargeting), the rank matching is right, the annealing lowers its energy
// within the radius for every cooling schedule, and the permutation cache is reused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include "prism/bluenoise/random.hpp"
#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/sorting.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace bn = prism::bluenoise;

namespace {

std::vector<float> randomValues(std::size_t n, std::uint64_t seed) {
    bn::SplitMix64 rng(seed);
    std::vector<float> v(n);
    for (float& x : v) x = static_cast<float>(rng.uniform());
    return v;
}
std::vector<std::uint32_t> randomTarget(std::size_t n, std::uint64_t seed) {
    bn::SplitMix64 rng(seed);
    std::vector<std::uint32_t> v(n);
    for (auto& x : v) x = static_cast<std::uint32_t>(rng.next());
    return v;
}
std::vector<std::uint32_t> blockSeeds(const std::vector<std::uint32_t>& seeds, int w, int h, int bx, int by, int b) {
    std::vector<std::uint32_t> out;
    for (int y = by; y < std::min(by + b, h); ++y)
        for (int x = bx; x < std::min(bx + b, w); ++x) out.push_back(seeds[static_cast<std::size_t>(y * w + x)]);
    std::sort(out.begin(), out.end());
    return out;
}
bn::Mask mask32() {
    static const bn::Mask m = bn::generateVoidAndCluster({.width = 32, .height = 32});
    return m;
}

}  // namespace

TEST(Sorting, SeedsStayAPermutationInEveryBlock) {
    const int w = 37, h = 29;  // partial blocks at the right and bottom
    for (int block : {4, 8, 16}) {
        std::vector<std::uint32_t> seeds = bn::initialSeeds(w, h, 3);
        const std::vector<std::uint32_t> before = seeds;
        std::vector<float> values = randomValues(static_cast<std::size_t>(w * h), 5);
        values[7] = std::nanf("");  // a broken pixel must not break the permutation
        bn::sortSeedsInBlocks(values, randomTarget(static_cast<std::size_t>(w * h), 6), w, h, block, seeds);
        EXPECT_NE(seeds, before);
        for (int by = 0; by < h; by += block)
            for (int bx = 0; bx < w; bx += block)
                EXPECT_EQ(blockSeeds(seeds, w, h, bx, by, block), blockSeeds(before, w, h, bx, by, block))
                    << "block " << bx << "," << by << " size " << block;
    }
}

TEST(Sorting, KthSmallestValueGoesToKthSmallestTarget) {
    const int w = 8, h = 8;
    std::vector<std::uint32_t> seeds(64);
    for (std::uint32_t i = 0; i < 64; ++i) seeds[i] = 1000 + i;  // seed = 1000 + pixel it rendered
    const std::vector<float> values = randomValues(64, 9);
    const std::vector<std::uint32_t> target = randomTarget(64, 10);
    bn::sortSeedsInBlocks(values, target, w, h, 8, seeds);
    std::vector<int> byValue(64), byTarget(64);
    for (int i = 0; i < 64; ++i) byValue[static_cast<std::size_t>(i)] = byTarget[static_cast<std::size_t>(i)] = i;
    std::sort(byValue.begin(), byValue.end(),
              [&](int a, int b) { return values[static_cast<std::size_t>(a)] < values[static_cast<std::size_t>(b)]; });
    std::sort(byTarget.begin(), byTarget.end(),
              [&](int a, int b) { return target[static_cast<std::size_t>(a)] < target[static_cast<std::size_t>(b)]; });
    for (std::size_t k = 0; k < 64; ++k)
        EXPECT_EQ(seeds[static_cast<std::size_t>(byTarget[k])], 1000u + static_cast<std::uint32_t>(byValue[k]));
}

TEST(Sorting, BadArgumentsThrow) {
    std::vector<std::uint32_t> seeds(4);
    EXPECT_THROW(bn::sortSeedsInBlocks(std::vector<float>(3), std::vector<std::uint32_t>(4), 2, 2, 4, seeds),
                 std::invalid_argument);
    EXPECT_THROW(bn::sortSeedsInBlocks(std::vector<float>(4), std::vector<std::uint32_t>(4), 2, 2, 0, seeds),
                 std::invalid_argument);
}

TEST(Retarget, AnnealingLowersEnergyWithinRadiusForEverySchedule) {
    bn::RetargetOptions o;
    o.epochs = 64;
    bn::frameShift(32, 32, o.shiftX, o.shiftY);
    for (auto schedule : {bn::CoolingSchedule::Hajek, bn::CoolingSchedule::Linear, bn::CoolingSchedule::Exponential,
                          bn::CoolingSchedule::Inverse}) {
        o.schedule = schedule;
        const bn::RetargetResult r = bn::computeRetarget(mask32(), o);
        std::printf("%s: energy %.1f -> %.1f, target %.1f -> %.1f, accepted %llu of %llu\n",
                    bn::coolingScheduleName(schedule), r.initialEnergy, r.finalEnergy, r.initialTarget, r.finalTarget,
                    (unsigned long long)r.accepted, (unsigned long long)r.moves);
        EXPECT_LT(r.finalEnergy, r.initialEnergy) << bn::coolingScheduleName(schedule);
        EXPECT_LT(r.finalTarget, 0.8 * r.initialTarget) << bn::coolingScheduleName(schedule);
        EXPECT_GT(r.accepted, 0u);
        // Exponential cooling (the thesis's choice) brings T much closer to the next mask.
        if (schedule == bn::CoolingSchedule::Exponential) {
            EXPECT_LT(r.finalTarget, 0.3 * r.initialTarget);
        }
        std::vector<std::uint32_t> sorted = r.permutation.source;
        std::sort(sorted.begin(), sorted.end());
        for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
        for (int m = 0; m < 32 * 32; ++m) {
            const int s = static_cast<int>(r.permutation.source[static_cast<std::size_t>(m)]);
            int dx = std::abs(s % 32 - m % 32), dy = std::abs(s / 32 - m / 32);
            dx = std::min(dx, 32 - dx), dy = std::min(dy, 32 - dy);
            ASSERT_LT(dx * dx + dy * dy, 36) << "pixel " << m << " moved beyond radius 6";
        }
    }
    EXPECT_EQ(bn::parseCoolingSchedule("hajek"), bn::CoolingSchedule::Hajek);
    EXPECT_THROW(bn::parseCoolingSchedule("quench"), std::invalid_argument);
}

TEST(Retarget, SortingThenRetargetingUsesEachSeedOncePerFrame) {
    bn::RetargetOptions o;
    o.epochs = 32;
    bn::frameShift(32, 32, o.shiftX, o.shiftY);
    const bn::RetargetPermutation p = bn::computeRetarget(mask32(), o).permutation;
    for (auto [w, h] : {std::pair{64, 64}, std::pair{75, 40}}) {  // a multiple of the mask, and not
        std::vector<std::uint32_t> seeds = bn::initialSeeds(w, h, 1);
        std::vector<std::uint32_t> all = seeds;
        std::sort(all.begin(), all.end());
        std::size_t moved = 0;
        for (int frame = 0; frame < 6; ++frame) {
            bn::sortSeedsInBlocks(randomValues(seeds.size(), 20 + static_cast<std::uint64_t>(frame)),
                                  randomTarget(seeds.size(), 40 + static_cast<std::uint64_t>(frame)), w, h, 8, seeds);
            const std::vector<std::uint32_t> before = seeds;
            bn::applyRetarget(p, frame * o.shiftX, frame * o.shiftY, w, h, seeds);
            for (std::size_t i = 0; i < seeds.size(); ++i) moved += seeds[i] != before[i];
            std::vector<std::uint32_t> now = seeds;
            std::sort(now.begin(), now.end());
            ASSERT_EQ(now, all) << w << "x" << h << " frame " << frame;
        }
        EXPECT_GT(moved, seeds.size()) << "the retargeting moved (almost) nothing";
    }
}

TEST(Retarget, PermutationIsCachedInAFile) {
    const auto path =
        std::filesystem::temp_directory_path() / ("prism_bn_retarget_" + std::to_string(::getpid()) + ".bin");
    std::filesystem::remove(path);
    bn::RetargetOptions o;
    o.epochs = 2;
    bool cached = true;
    const bn::RetargetPermutation a = bn::loadOrComputeRetarget(mask32(), o, path, &cached);
    EXPECT_FALSE(cached);
    const bn::RetargetPermutation b = bn::loadOrComputeRetarget(mask32(), o, path, &cached);
    EXPECT_TRUE(cached);
    EXPECT_EQ(a.source, b.source);
    o.radius = 4;  // other options: recomputed
    bn::loadOrComputeRetarget(mask32(), o, path, &cached);
    EXPECT_FALSE(cached);
    {
        std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(-4, std::ios::end);
        const std::uint32_t bogus = 0xFFFFFFFFu;  // not a pixel index: the cache is rejected
        f.write(reinterpret_cast<const char*>(&bogus), 4);
    }
    bn::loadOrComputeRetarget(mask32(), o, path, &cached);
    EXPECT_FALSE(cached);
    std::filesystem::remove(path);
}

TEST(Retarget, ExtremesAndBadOptions) {
    bn::RetargetOptions o;
    o.epochs = 3;
    // The smallest masks: 2x1 and 3x3 (the radius window wraps onto itself).
    for (auto [w, h] : {std::pair{2, 1}, std::pair{3, 3}}) {
        const bn::Mask m = bn::generateVoidAndCluster({.width = w, .height = h});
        const bn::RetargetResult r = bn::computeRetarget(m, o);
        std::vector<std::uint32_t> sorted = r.permutation.source;
        std::sort(sorted.begin(), sorted.end());
        for (std::uint32_t i = 0; i < sorted.size(); ++i) EXPECT_EQ(sorted[i], i);
        EXPECT_TRUE(std::isfinite(r.finalEnergy));
    }
    EXPECT_THROW(bn::computeRetarget(bn::generateVoidAndCluster({.width = 1, .height = 1}), o), std::invalid_argument);
    o.radius = 1;  // no pixel is closer than 1: no move possible
    EXPECT_THROW(bn::computeRetarget(mask32(), o), std::invalid_argument);
    o.radius = 6;
    o.sigmaI = 0.0;
    EXPECT_THROW(bn::computeRetarget(mask32(), o), std::invalid_argument);
    o.sigmaI = 2.1;
    o.alpha = std::nan("");
    EXPECT_THROW(bn::computeRetarget(mask32(), o), std::invalid_argument);
}
