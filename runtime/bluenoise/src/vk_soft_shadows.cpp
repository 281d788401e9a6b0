// Vulkan frames of the soft-shadow demo (see prism/bluenoise/vk_soft_shadows.hpp).
#include "prism/bluenoise/vk_soft_shadows.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "prism/bluenoise_shaders.hpp"
#include "prism/vk/buffer.hpp"
#include "prism/vk/texture.hpp"
#include "prism/vk/uniform_block.hpp"

namespace prism::bluenoise {
namespace {

const catalog::Variant& softShadowsVariant() {
    const auto* shader = catalog::findShader(bluenoise_shaders::kCatalog, "soft_shadows");
    const auto* variant = shader ? catalog::findVariant(*shader, {}) : nullptr;
    if (variant == nullptr) throw std::logic_error("the blue-noise catalogue has no soft_shadows program");
    return *variant;
}

vk::Texture uintTexture(const vk::Device& device, int width, int height, const std::vector<std::uint32_t>& values) {
    return vk::Texture(device, {VK_IMAGE_VIEW_TYPE_2D, width, height, 1, VK_FORMAT_R32_UINT, VK_FILTER_NEAREST},
                       values.data(), values.size() * sizeof(std::uint32_t));
}

void setUniforms(vk::UniformBlock& block, const SoftShadowUniforms& u) {
    block.set("u_blueNoiseStackDepth", u.stackDepth);
    block.set("u_blueNoiseSampler", u.sampler);
    block.set("u_spp", u.spp);
    block.set("u_imageSize", glm::vec2(u.imageSize[0], u.imageSize[1]));
    block.set("u_extent", u.extent);
    block.set("u_light", glm::vec4(u.light[0], u.light[1], u.light[2], u.light[3]));
    const char* names[kGpuSpheres] = {"u_sphere0", "u_sphere1", "u_sphere2"};
    for (std::size_t i = 0; i < kGpuSpheres; ++i)
        block.set(names[i], glm::vec4(u.spheres[i][0], u.spheres[i][1], u.spheres[i][2], u.spheres[i][3]));
}

}  // namespace

VulkanSoftShadows::VulkanSoftShadows(const vk::Device& device, int width, int height, vk::ClipConvention clip)
    : device_(&device),
      clip_(clip),
      target_(device, width, height, vk::RenderTarget::kFloatColorFormat),
      pipeline_(device, target_, softShadowsVariant(), {}, {.label = "soft_shadows", .clip = clip}) {}

RealImage VulkanSoftShadows::render(const SoftShadowScene& scene, StochasticSetup& setup,
                                    const RenderOptions& options) {
    const SoftShadowUniforms u = softShadowUniforms(scene, setup.tables, options);  // throws for > 3 spheres
    if (options.width != target_.width() || options.height != target_.height())
        throw std::invalid_argument("prism::bluenoise::VulkanSoftShadows: options size differs from the target's");
    vk::UniformBlock block(*pipeline_.uniformBlock(), "soft_shadows");
    setUniforms(block, u);
    vk::Buffer uniforms(*device_, block.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    vk::DescriptorSets sets(*device_, pipeline_);
    sets.bindBuffer(*pipeline_.uniformBlock(), uniforms);
    const SamplerTables& t = setup.tables;
    const vk::Texture mask = uintTexture(*device_, t.maskWidth, t.maskHeight, t.mask);
    const vk::Texture stack = uintTexture(*device_, t.stackWidth, t.stackHeight * t.stackDepth, t.stack);
    sets.bindImage(pipeline_.resource("u_blueNoiseMask"), mask.view(), mask.sampler());
    sets.bindImage(pipeline_.resource("u_blueNoiseStack"), stack.view(), stack.sampler());
    return runSoftShadowPipeline(setup, options, [&](const SamplerTables& tables, std::uint32_t frame) {
        const vk::Texture seeds = uintTexture(*device_, tables.seedWidth, tables.seedHeight, tables.seeds);
        sets.bindImage(pipeline_.resource("u_blueNoiseSeeds"), seeds.view(), seeds.sampler());
        block.set("u_frame", static_cast<unsigned>(frame));
        uniforms.write(block.bytes().data(), block.bytes().size());
        device_->submit([&](VkCommandBuffer cmd) {
            target_.begin(cmd, {0.0f, 0.0f, 0.0f, 1.0f});
            pipeline_.bind(cmd, target_.width(), target_.height());
            sets.bind(cmd, pipeline_);
            vkCmdDraw(cmd, 3, 1, 0, 0);
            target_.end(cmd);
        });
        const image::ImageF pixels = target_.readImageF(clip_);
        std::vector<double> values(static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height));
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = pixels.data[i * 4];
        return values;
    });
}

}  // namespace prism::bluenoise
