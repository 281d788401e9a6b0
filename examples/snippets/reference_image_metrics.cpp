// The usage example of prism/reference/image_metrics.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/reference/image_metrics.hpp"
// [/snippet]

int main() {
    // Alpha marks coverage: the reference covers pixel (1, 1); the render covers it 3 units
    // brighter in red and also covers (2, 2), which the reference does not.
    prism::image::Image8 reference(4, 4, {10, 10, 10, 0}), render(4, 4, {10, 10, 10, 0});
    reference.data[reference.offset(1, 1)] = 100, reference.data[reference.offset(1, 1) + 3] = 255;
    render.data[render.offset(1, 1)] = 103, render.data[render.offset(1, 1) + 3] = 255;
    render.data[render.offset(2, 2)] = 50, render.data[render.offset(2, 2) + 3] = 255;
    // [snippet]
    prism::reference::Metrics m = prism::reference::compareWithReference(render, reference);
    // m.union_.mean, m.union_.max: |render - reference| over R, G, B of pixels either covers
    // m.interior.max: where both cover; m.renderOnly + m.referenceOnly: silhouette mismatch
    // [/snippet]
    const bool interior = m.interior.pixels == 1 && m.interior.max == 3;
    const bool silhouette = m.renderOnly == 1 && m.referenceOnly == 0;
    const bool unionStats = m.union_.pixels == 2 && m.union_.max == 40 && m.union_.mean == (3.0 + 40.0) / 6.0;
    return interior && silhouette && unionStats ? 0 : 1;
}
