// Pipelines from a catalogue variant's SPIR-V and reflection, and their descriptor sets
// (see prism/vk/pipeline.hpp).
#include "prism/vk/pipeline.hpp"

#include <algorithm>
#include <stdexcept>

namespace prism::vk {
namespace {

VkShaderStageFlagBits stageBit(catalog::Stage stage) {
    switch (stage) {
        case catalog::Stage::Vertex: return VK_SHADER_STAGE_VERTEX_BIT;
        case catalog::Stage::Fragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
        case catalog::Stage::Geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
        case catalog::Stage::TessControl: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
        case catalog::Stage::TessEvaluation: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
        default:
            throw std::invalid_argument("a " + std::string(catalog::stageName(stage)) +
                                        " stage cannot be part of a graphics pipeline");
    }
}

VkDescriptorType descriptorType(catalog::ResourceKind kind) {
    switch (kind) {
        case catalog::ResourceKind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case catalog::ResourceKind::StorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case catalog::ResourceKind::CombinedImageSampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case catalog::ResourceKind::SampledImage: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case catalog::ResourceKind::StorageImage: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        case catalog::ResourceKind::Sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
        case catalog::ResourceKind::UniformTexelBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
        case catalog::ResourceKind::StorageTexelBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
        case catalog::ResourceKind::InputAttachment: return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
        default: break;
    }
    throw std::invalid_argument("prism::vk has no graphics descriptor for a " +
                                std::string(catalog::resourceKindName(kind)));
}

// One layout per set number 0..max, each with the variant's bindings of that set.
std::vector<DescriptorSetLayout> createSetLayouts(VkDevice device, const catalog::Variant& variant) {
    std::uint32_t sets = 0;
    for (const auto& r : variant.resources) sets = std::max(sets, r.set + 1);
    std::vector<DescriptorSetLayout> layouts;
    for (std::uint32_t set = 0; set < sets; ++set) {
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (const auto& r : variant.resources)
            if (r.set == set)
                bindings.push_back({r.binding, descriptorType(r.kind), std::max(r.arraySize, 1u),
                                    VK_SHADER_STAGE_ALL_GRAPHICS, nullptr});
        VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        info.bindingCount = static_cast<std::uint32_t>(bindings.size());
        info.pBindings = bindings.data();
        VkDescriptorSetLayout layout = VK_NULL_HANDLE;
        check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "vkCreateDescriptorSetLayout");
        layouts.emplace_back(device, layout);
    }
    return layouts;
}

// The vertex input state: stream i at binding i; each SPIR-V input at its location.
struct VertexInput {
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
};

VertexInput vertexInput(const catalog::Variant& variant, std::span<const VertexStream> streams,
                        const std::string& label) {
    VertexInput in;
    for (std::uint32_t i = 0; i < streams.size(); ++i)
        in.bindings.push_back({i, streams[i].stride, VK_VERTEX_INPUT_RATE_VERTEX});
    for (const auto& input : variant.spirvInputs) {
        if (!input.used) continue;  // declared, never read: no stream needs to feed it
        auto it =
            std::find_if(streams.begin(), streams.end(), [&](const auto& s) { return s.attribute == input.name; });
        if (it == streams.end()) {
            std::string fed;
            for (const auto& s : streams) fed += (fed.empty() ? "" : ", ") + std::string(s.attribute);
            throw std::invalid_argument(label + ": the shader reads vertex input '" + std::string(input.name) +
                                        "', which no vertex stream feeds (streams: " + fed + ")");
        }
        in.attributes.push_back({static_cast<std::uint32_t>(input.location),
                                 static_cast<std::uint32_t>(it - streams.begin()), it->format, 0});
    }
    return in;
}

std::vector<ShaderModule> createModules(VkDevice device, const catalog::Variant& variant, const std::string& label) {
    std::vector<ShaderModule> modules;
    for (const auto& stage : variant.stages) {
        if (stage.spirv.empty())
            throw std::invalid_argument(label + " (" + std::string(variant.name) +
                                        ") has no SPIR-V; build its catalogue with prism_add_shaders(... TARGETS gl "
                                        "spirv) (docs/targets.md)");
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = stage.spirv.size_bytes();
        info.pCode = stage.spirv.data();
        VkShaderModule module = VK_NULL_HANDLE;
        check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule for " + label);
        modules.emplace_back(device, module);
    }
    return modules;
}

// The fixed-function state of Prism's draws (depth LESS with writes, no blending).
struct FixedState {
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    VkPipelineViewportDepthClipControlCreateInfoEXT depthRange{};
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    VkPipelineRasterizationProvokingVertexStateCreateInfoEXT provoking{};
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    VkPipelineColorBlendAttachmentState blendAttachment{};
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    VkDynamicState dynamic[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamicState{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};

    explicit FixedState(const PipelineOptions& options) {
        assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        viewport.viewportCount = 1;
        viewport.scissorCount = 1;
        options.clip.chainDepthRange(viewport, depthRange);
        raster.polygonMode = VK_POLYGON_MODE_FILL;
        raster.cullMode = options.cull;
        raster.frontFace = options.clip.frontFace();
        raster.lineWidth = 1.0f;
        options.clip.chainProvokingVertex(raster, provoking);
        multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        depth.depthTestEnable = VK_TRUE;
        depth.depthWriteEnable = VK_TRUE;
        depth.depthCompareOp = VK_COMPARE_OP_LESS;
        blendAttachment.colorWriteMask =
            VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        blend.attachmentCount = 1;
        blend.pAttachments = &blendAttachment;
        dynamicState.dynamicStateCount = 2;
        dynamicState.pDynamicStates = dynamic;
    }
    FixedState(const FixedState&) = delete;  // holds pointers into itself
};

}  // namespace

Pipeline::Pipeline(const Device& device, const RenderTarget& target, const catalog::Variant& variant,
                   std::span<const VertexStream> streams, PipelineOptions options)
    : variant_(&variant), options_(std::move(options)) {
    const VkDevice dev = device.device();
    const auto modules = createModules(dev, variant, options_.label);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (std::size_t i = 0; i < modules.size(); ++i)
        stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
                          stageBit(variant.stages[i].stage), modules[i].get(), "main", nullptr});
    const VertexInput input = vertexInput(variant, streams, options_.label);
    VkPipelineVertexInputStateCreateInfo vertexState{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexState.vertexBindingDescriptionCount = static_cast<std::uint32_t>(input.bindings.size());
    vertexState.pVertexBindingDescriptions = input.bindings.data();
    vertexState.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(input.attributes.size());
    vertexState.pVertexAttributeDescriptions = input.attributes.data();

    setLayouts_ = createSetLayouts(dev, variant);
    std::vector<VkDescriptorSetLayout> rawLayouts;
    for (const auto& l : setLayouts_) rawLayouts.push_back(l.get());
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = static_cast<std::uint32_t>(rawLayouts.size());
    layoutInfo.pSetLayouts = rawLayouts.data();
    VkPipelineLayout layout = VK_NULL_HANDLE;
    check(vkCreatePipelineLayout(dev, &layoutInfo, nullptr, &layout), "vkCreatePipelineLayout");
    layout_ = PipelineLayout(dev, layout);

    const FixedState fixed(options_);
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = static_cast<std::uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexState;
    info.pInputAssemblyState = &fixed.assembly;
    info.pViewportState = &fixed.viewport;
    info.pRasterizationState = &fixed.raster;
    info.pMultisampleState = &fixed.multisample;
    info.pDepthStencilState = &fixed.depth;
    info.pColorBlendState = &fixed.blend;
    info.pDynamicState = &fixed.dynamicState;
    info.layout = layout;
    info.renderPass = target.renderPass();
    VkPipeline pipeline = VK_NULL_HANDLE;
    check(vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
          "vkCreateGraphicsPipelines for " + options_.label);
    pipeline_ = PipelineObject(dev, pipeline);
}

const catalog::Resource* Pipeline::uniformBlock() const {
    for (const auto& r : variant_->resources)
        if (r.kind == catalog::ResourceKind::UniformBuffer) return &r;
    return nullptr;
}

const catalog::Resource& Pipeline::resource(std::string_view name) const {
    std::string known;
    for (const auto& r : variant_->resources) {
        if (r.name == name) return r;
        known += (known.empty() ? "" : ", ") + std::string(r.name);
    }
    throw std::invalid_argument(options_.label + ": the shader has no descriptor '" + std::string(name) +
                                "' (it has: " + known + ")");
}

void Pipeline::bind(VkCommandBuffer cmd, int width, int height) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    const VkViewport viewport = options_.clip.viewport(width, height);
    const VkRect2D scissor{{0, 0}, {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

DescriptorSets::DescriptorSets(const Device& device, const Pipeline& pipeline) : device_(device.device()) {
    const auto& layouts = pipeline.setLayouts();
    if (layouts.empty()) return;
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& r : pipeline.variant().resources)
        sizes.push_back({descriptorType(r.kind), std::max(r.arraySize, 1u)});
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = static_cast<std::uint32_t>(layouts.size());
    poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    check(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool), "vkCreateDescriptorPool");
    pool_ = DescriptorPool(device_, pool);
    std::vector<VkDescriptorSetLayout> raw;
    for (const auto& l : layouts) raw.push_back(l.get());
    VkDescriptorSetAllocateInfo allocate{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocate.descriptorPool = pool;
    allocate.descriptorSetCount = static_cast<std::uint32_t>(raw.size());
    allocate.pSetLayouts = raw.data();
    sets_.resize(raw.size());
    check(vkAllocateDescriptorSets(device_, &allocate, sets_.data()), "vkAllocateDescriptorSets");
}

void DescriptorSets::write(const catalog::Resource& resource, const VkDescriptorBufferInfo* buffer,
                           const VkDescriptorImageInfo* image) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = sets_.at(resource.set);
    write.dstBinding = resource.binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptorType(resource.kind);
    write.pBufferInfo = buffer;
    write.pImageInfo = image;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void DescriptorSets::bindBuffer(const catalog::Resource& resource, const Buffer& buffer) {
    const VkDescriptorBufferInfo info{buffer.get(), 0, VK_WHOLE_SIZE};
    write(resource, &info, nullptr);
}

void DescriptorSets::bindImage(const catalog::Resource& resource, VkImageView view, VkSampler sampler) {
    const VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    write(resource, nullptr, &info);
}

void DescriptorSets::bind(VkCommandBuffer cmd, const Pipeline& pipeline) const {
    if (sets_.empty()) return;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0,
                            static_cast<std::uint32_t>(sets_.size()), sets_.data(), 0, nullptr);
}

}  // namespace prism::vk
