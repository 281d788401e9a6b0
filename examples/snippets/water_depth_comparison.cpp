// The usage example of prism/water/depth_comparison.hpp, compiled and run by tests/snippets.
#include <cmath>

// [snippet]
#include "prism/water/depth_comparison.hpp"
using namespace prism::water;
// [/snippet]

int main() {
    // [snippet]
    std::vector<float> fine(512 * 512, 0.002f), coarse(64 * 64, 0.0025f);
    std::vector<float> common = resampleDepth(fine, 512, 512, 64, 64);  // 64 x 64 means
    DepthComparison c = compareDepth(coarse, common);                   // meanAbsMm 0.5, both wetted
    // [/snippet]
    const bool ok = common.size() == 64u * 64u && std::abs(c.meanAbsMm - 0.5) < 1e-4 && c.wettedShare == 1.0 &&
                    c.referenceWettedShare == 1.0;
    return ok ? 0 : 1;
}
