// The usage example of prism/bluenoise/vk_soft_shadows.hpp, compiled and run by tests/snippets
// (lavapipe, no GL).
#include <cmath>

// [snippet]
#include "prism/bluenoise/vk_soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
namespace bn = prism::bluenoise;
// [/snippet]

int main() {
    // [snippet]
    prism::vk::Device device;
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 32, .height = 32}));
    bn::RenderOptions options;
    options.width = options.height = 32;
    options.sampler = bn::SamplerKind::BlueNoise;
    bn::VulkanSoftShadows gpu(device, 32, 32);
    bn::RealImage image = gpu.render(bn::SoftShadowScene::classic(), setup, options);
    // [/snippet]
    return image.values.size() == 32u * 32u && std::isfinite(image.values[0]) ? 0 : 1;
}
