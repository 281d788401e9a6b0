// A graphics pipeline built from a catalogue variant's SPIR-V (the spirv target, or a
// Vulkan-client catalogue), its descriptor set layouts from the variant's reflection, its
// vertex input from the variant's SPIR-V inputs, and descriptor sets to bind resources.
//
// Usage (snippet: examples/snippets/vk_pipeline.cpp):
//
//     #include "prism/vk/pipeline.hpp"
//     #include "prism/vk/uniform_block.hpp"
//     // device, target: prism/vk/device.hpp, prism/vk/render_target.hpp
//     const prism::vk::VertexStream streams[] = {{"a_position", VK_FORMAT_R32G32B32_SFLOAT, 12},
//                                                {"a_normal", VK_FORMAT_R32G32B32_SFLOAT, 12}};
//     prism::vk::Pipeline pipeline(device, target, *variant, streams, {.label = "phong"});
//     prism::vk::UniformBlock block(*pipeline.uniformBlock(), "phong");
//     block.set("u_color", glm::vec4(1, 0, 0, 1));  // by name, at the reflected offset
//     prism::vk::Buffer uniforms(device, block.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
//     uniforms.write(block.bytes().data(), block.bytes().size());
//     prism::vk::DescriptorSets sets(device, pipeline);
//     sets.bindBuffer(*pipeline.uniformBlock(), uniforms);
//     // in a render pass: pipeline.bind(cmd, w, h); sets.bind(cmd, pipeline); vertex buffers; vkCmdDrawIndexed
//
// Stream i is vertex binding i; each SPIR-V input reads the stream of its name at its
// location (the variant's `spirvInputs`). An input the shader reads that no stream feeds
// throws std::invalid_argument naming it: it would otherwise read zeros and draw nothing;
// a declared input the stage never reads (`used` false) needs no stream.
// Depth test LESS with writes, no blending, as Prism's GL renders; the viewport follows
// the ClipConvention (prism/vk/clip_convention.hpp). Move-only.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/vk/buffer.hpp"
#include "prism/vk/clip_convention.hpp"
#include "prism/vk/device.hpp"
#include "prism/vk/handles.hpp"
#include "prism/vk/render_target.hpp"

namespace prism::vk {

// One vertex buffer: the attribute it feeds, its format and its stride in bytes.
struct VertexStream {
    std::string_view attribute;
    VkFormat format;
    std::uint32_t stride;
};

struct PipelineOptions {
    std::string label;  // names the program in errors
    VkCullModeFlags cull = VK_CULL_MODE_NONE;
    ClipConvention clip;
};

class Pipeline {
  public:
    Pipeline(const Device& device, const RenderTarget& target, const catalog::Variant& variant,
             std::span<const VertexStream> streams, PipelineOptions options = {});

    VkPipeline get() const { return pipeline_.get(); }
    VkPipelineLayout layout() const { return layout_.get(); }
    const std::vector<DescriptorSetLayout>& setLayouts() const { return setLayouts_; }
    const catalog::Variant& variant() const { return *variant_; }
    const std::string& label() const { return options_.label; }
    // The variant's uniform buffer (gl_DefaultUniformBlock for the spirv target); nullptr when it has none.
    const catalog::Resource* uniformBlock() const;
    // The variant's descriptor named `name` (a sampler uniform such as "u_diffractionTables"),
    // with the set and binding its SPIR-V uses; throws std::invalid_argument naming the
    // pipeline and the descriptors it has.
    const catalog::Resource& resource(std::string_view name) const;

    // Binds the pipeline and sets the viewport and scissor of a `width` x `height` target.
    void bind(VkCommandBuffer cmd, int width, int height) const;

  private:
    const catalog::Variant* variant_;
    PipelineOptions options_;
    std::vector<DescriptorSetLayout> setLayouts_;  // one per set number, 0..max
    PipelineLayout layout_;
    PipelineObject pipeline_;
};

// One descriptor set per set layout of a pipeline, from a pool of their own: a draw's
// resources. Move-only.
class DescriptorSets {
  public:
    DescriptorSets(const Device& device, const Pipeline& pipeline);
    // Points `resource` (a UniformBuffer or StorageBuffer) at the whole of `buffer`.
    void bindBuffer(const catalog::Resource& resource, const Buffer& buffer);
    // Points `resource` (a CombinedImageSampler) at `view` sampled with `sampler`.
    void bindImage(const catalog::Resource& resource, VkImageView view, VkSampler sampler);
    void bind(VkCommandBuffer cmd, const Pipeline& pipeline) const;

  private:
    void write(const catalog::Resource& resource, const VkDescriptorBufferInfo* buffer,
               const VkDescriptorImageInfo* image);
    VkDevice device_;
    DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
};

}  // namespace prism::vk
