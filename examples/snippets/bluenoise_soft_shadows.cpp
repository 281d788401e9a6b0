// The usage example of prism/bluenoise/soft_shadows.hpp, compiled and run by tests/snippets.
#include <algorithm>
#include <cmath>

// [snippet]
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
// [/snippet]

int main() {
    // [snippet]
    namespace bn = prism::bluenoise;
    bn::SoftShadowScene scene = bn::SoftShadowScene::classic();
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
    bn::RenderOptions options;
    options.width = options.height = 32;
    options.sampler = bn::SamplerKind::BlueNoise;
    bn::RealImage image = bn::renderSoftShadows(scene, setup, options);  // 1 spp, frame 0
    bn::Reference reference = bn::renderReference(scene, 32, 32, 1024);
    bn::ErrorStats error = bn::compareToReference(image, reference);
    // [/snippet]
    // Some pixels in penumbrae, an error that is not zero at 1 spp but well below the signal,
    // and 1.0 (unoccluded, below the light's centre) at most a little exceeded.
    double maxValue = 0.0;
    for (double v : image.values) maxValue = std::max(maxValue, v);
    return image.width == 32 && image.values.size() == 32u * 32u && error.pixels > 0 && error.rms > 0.0 &&
                   error.rms < 0.5 && maxValue > 0.5 && maxValue < 1.5
               ? 0
               : 1;
}
