// Resampling water maps onto a common grid and comparing them (depth_comparison.hpp): the
// node-to-cell assignment on a hand-worked 5 x 5 -> 3 x 3 case, identity at equal sizes,
// a constant kept at every ratio, and the depth and wetted-area errors on known maps.
#include <gtest/gtest.h>

#include <vector>

#include "prism/water/depth_comparison.hpp"

namespace prism::water {
namespace {

TEST(DepthComparison, ResamplingAveragesTheSourceNodesInEachTargetCell) {
    // Along a row of 5 nodes (at 0, 1/4, 1/2, 3/4, 1) the 3 target cells [-1/4, 1/4),
    // [1/4, 3/4), [3/4, 5/4) hold nodes {0}, {1, 2}, {3, 4}; the same along columns.
    std::vector<float> depth(25);
    for (int z = 0; z < 5; ++z)
        for (int x = 0; x < 5; ++x) depth[static_cast<std::size_t>(z * 5 + x)] = static_cast<float>(x + 10 * z);
    const std::vector<float> out = resampleDepth(depth, 5, 5, 3, 3);
    const float column[3] = {0.0f, 1.5f, 3.5f}, row[3] = {0.0f, 15.0f, 35.0f};
    for (int z = 0; z < 3; ++z)
        for (int x = 0; x < 3; ++x)
            EXPECT_FLOAT_EQ(out[static_cast<std::size_t>(z * 3 + x)], column[x] + row[z]) << x << "," << z;
}

TEST(DepthComparison, EqualSizesCopyAndAConstantStaysConstant) {
    const std::vector<float> ramp = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(resampleDepth(ramp, 3, 2, 3, 2), ramp);
    for (int from : {64, 100, 128, 512}) {
        const std::vector<float> out =
            resampleDepth(std::vector<float>(static_cast<std::size_t>(from * from), 0.25f), from, from, 64, 64);
        for (float v : out) ASSERT_FLOAT_EQ(v, 0.25f) << from;
    }
    EXPECT_THROW(resampleDepth(ramp, 3, 2, 4, 2), std::invalid_argument);
    EXPECT_THROW(resampleDepth(ramp, 2, 2, 2, 2), std::invalid_argument);
}

TEST(DepthComparison, MeanP95AndWettedAreaOfKnownMaps) {
    // 100 cells: the reference is 2 mm everywhere; the map is 2 mm, except 10 cells at
    // 0.5 mm (dry at the 1 mm threshold, 1.5 mm off) and 5 cells at 7 mm (5 mm off).
    std::vector<float> reference(100, 0.002f), depth(100, 0.002f);
    for (int i = 0; i < 10; ++i) depth[static_cast<std::size_t>(i)] = 0.0005f;
    for (int i = 10; i < 15; ++i) depth[static_cast<std::size_t>(i)] = 0.007f;
    const DepthComparison c = compareDepth(depth, reference);
    EXPECT_NEAR(c.meanAbsMm, (10 * 1.5 + 5 * 5.0) / 100.0, 1e-6);
    EXPECT_NEAR(c.p95AbsMm, 1.5, 1e-6);  // the 95th of 100 sorted differences
    EXPECT_DOUBLE_EQ(c.wettedShare, 0.9);
    EXPECT_DOUBLE_EQ(c.referenceWettedShare, 1.0);
    EXPECT_NEAR(c.wettedAreaError(), 0.1, 1e-12);
    EXPECT_THROW(compareDepth(depth, std::vector<float>(99, 0.0f)), std::invalid_argument);
}

}  // namespace
}  // namespace prism::water
