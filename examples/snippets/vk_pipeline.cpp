// The usage example of prism/vk/pipeline.hpp, compiled and run by tests/snippets: phong's
// pipeline from the catalogue's SPIR-V, its uniform block filled by name, its descriptors.
#include "prism/shaders.hpp"
#include "prism/vk/render_target.hpp"
// [snippet]
#include "prism/vk/pipeline.hpp"
#include "prism/vk/uniform_block.hpp"
// [/snippet]

int main() {
    prism::vk::Device device({.validation = true});
    prism::vk::RenderTarget target(device, 64, 64);
    const auto* variant = &prism::shaders::shaderInfo(prism::shaders::ShaderId::phong).variants[0];
    // [snippet]
    // device, target: prism/vk/device.hpp, prism/vk/render_target.hpp
    const prism::vk::VertexStream streams[] = {{"a_position", VK_FORMAT_R32G32B32_SFLOAT, 12},
                                               {"a_normal", VK_FORMAT_R32G32B32_SFLOAT, 12}};
    prism::vk::Pipeline pipeline(device, target, *variant, streams, {.label = "phong"});
    prism::vk::UniformBlock block(*pipeline.uniformBlock(), "phong");
    block.set("u_color", glm::vec4(1, 0, 0, 1));  // by name, at the reflected offset
    prism::vk::Buffer uniforms(device, block.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    uniforms.write(block.bytes().data(), block.bytes().size());
    prism::vk::DescriptorSets sets(device, pipeline);
    sets.bindBuffer(*pipeline.uniformBlock(), uniforms);
    // in a render pass: pipeline.bind(cmd, w, h); sets.bind(cmd, pipeline); vertex buffers; vkCmdDrawIndexed
    // [/snippet]
    return pipeline.get() != VK_NULL_HANDLE && device.validationMessages().empty() ? 0 : 1;
}
