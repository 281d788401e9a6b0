// Catalogue renders through Vulkan (see prism/render/vulkan_render.hpp).
#include "prism/render/vulkan_render.hpp"

#include <stdexcept>

#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"

namespace prism::render {

// What one draw holds until the frame is submitted.
struct VulkanRenderer::DrawResources {
    const vk::Pipeline* pipeline = nullptr;
    vk::Buffer positions, normals, indices, uniforms;
    std::unique_ptr<vk::DescriptorSets> sets;
    std::vector<vk::Texture> textures;  // the draw's extras' images, bound in sets
    std::uint32_t indexCount = 0;
};

namespace {

constexpr vk::VertexStream kStreams[] = {{"a_position", VK_FORMAT_R32G32B32_SFLOAT, sizeof(glm::vec3)},
                                         {"a_normal", VK_FORMAT_R32G32B32_SFLOAT, sizeof(glm::vec3)}};

template <class T>
vk::Buffer upload(const vk::Device& device, const std::vector<T>& data, VkBufferUsageFlags usage) {
    vk::Buffer buffer(device, data.size() * sizeof(T), usage);
    buffer.write(data.data(), data.size() * sizeof(T));
    return buffer;
}

}  // namespace

VulkanFrame frameOf(const RenderJob& job) {
    VulkanFrame frame;
    frame.camera = job.camera;
    frame.lights = job.lights;
    frame.fog = job.fog;
    frame.width = job.width;
    frame.height = job.height;
    frame.background = job.background;
    frame.draws.push_back({job.shader, job.variant, job.mesh, job.world, job.material, nullptr, nullptr});
    return frame;
}

RenderJob jobOf(const VulkanFrame& frame, const VulkanDraw& draw) {
    RenderJob job;
    job.shader = draw.shader;
    job.variant = draw.variant;
    job.mesh = draw.mesh;
    job.world = draw.world;
    job.material = draw.material;
    job.lights = frame.lights;
    job.fog = frame.fog;
    job.camera = frame.camera;
    job.width = frame.width;
    job.height = frame.height;
    job.background = frame.background;
    return job;
}

VulkanRenderer::VulkanRenderer(const catalog::Catalog& catalog, VulkanRenderOptions options)
    : variants_(catalog), options_(options), device_(options.device) {}

VulkanRenderer::~VulkanRenderer() = default;

const vk::Pipeline& VulkanRenderer::pipelineFor(const catalog::Variant& variant, const std::string& label,
                                                const vk::RenderTarget& target) {
    auto it = pipelines_.find(&variant);
    if (it == pipelines_.end()) {
        vk::PipelineOptions options{label, options_.cull, options_.clip};
        auto pipeline = std::make_unique<vk::Pipeline>(device_, target, variant, kStreams, options);
        it = pipelines_.emplace(&variant, std::move(pipeline)).first;
    }
    return *it->second;
}

ProgramCache& VulkanRenderer::variantsOf(const catalog::Catalog* catalog) {
    if (catalog == nullptr || catalog == &variants_.catalog()) return variants_;
    auto& cache = otherCatalogs_[catalog];
    if (!cache) cache = std::make_unique<ProgramCache>(*catalog);
    return *cache;
}

// The draw's variant, pipeline, vertex buffers (a constant (0, 0, 1) normal without
// normals, as GpuMesh) and uniform block, filled as GL's setFrameUniforms fills a program.
VulkanRenderer::DrawResources VulkanRenderer::prepare(const VulkanFrame& frame, const VulkanDraw& draw,
                                                      const vk::RenderTarget& target) {
    geometry::requireValidMesh(draw.mesh, "VulkanRenderer");
    ProgramCache& variants = variantsOf(draw.catalog);
    const auto* shader = catalog::findShader(variants.catalog(), draw.shader);
    if (!shader) (void)variants.variantOf(draw.shader, {});  // throws UnknownShaderError with the list
    const VariantValues values = variantFor(*shader, featuresOf(frame.lights, frame.fog.has_value()), draw.variant);
    const catalog::Variant& variant = variants.variantOf(draw.shader, values);
    const std::string label = draw.shader + " (" + std::string(variant.name) + ")";
    DrawResources r;
    r.pipeline = &pipelineFor(variant, label, target);
    r.positions = upload(device_, draw.mesh.positions, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    r.normals = draw.mesh.normals.empty()
                    ? upload(device_, std::vector<glm::vec3>(draw.mesh.positions.size(), glm::vec3(0, 0, 1)),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT)
                    : upload(device_, draw.mesh.normals, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    r.indices = upload(device_, draw.mesh.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    r.indexCount = static_cast<std::uint32_t>(draw.mesh.indices.size());
    r.sets = std::make_unique<vk::DescriptorSets>(device_, *r.pipeline);
    if (const catalog::Resource* block = r.pipeline->uniformBlock()) {
        vk::UniformBlock uniforms(*block, label, options_.uniformOffsetFault);
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        setFrameUniforms(uniforms, frame.camera, aspect, frame.lights, draw.world, draw.material,
                         frame.fog ? &*frame.fog : nullptr);
        if (draw.extras) r.textures = draw.extras->apply(device_, *r.pipeline, uniforms, *r.sets);
        r.uniforms = vk::Buffer(device_, uniforms.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        r.uniforms.write(uniforms.bytes().data(), uniforms.bytes().size());
        r.sets->bindBuffer(*block, r.uniforms);
    } else if (draw.extras) {  // its uniforms and textures would be silently dropped
        throw std::invalid_argument(label + ": the draw carries extras, but the shader has no uniform block for them");
    }
    return r;
}

image::Image8 VulkanRenderer::render(const VulkanFrame& frame) {
    vk::RenderTarget target(device_, frame.width, frame.height);
    std::vector<DrawResources> draws;
    for (const auto& draw : frame.draws) draws.push_back(prepare(frame, draw, target));
    device_.submit([&](VkCommandBuffer cmd) {
        target.begin(cmd, {frame.background.r, frame.background.g, frame.background.b, frame.background.a});
        for (const auto& d : draws) {
            d.pipeline->bind(cmd, frame.width, frame.height);
            d.sets->bind(cmd, *d.pipeline);
            const VkBuffer buffers[] = {d.positions.get(), d.normals.get()};
            const VkDeviceSize offsets[] = {0, 0};
            vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
            vkCmdBindIndexBuffer(cmd, d.indices.get(), 0, VK_INDEX_TYPE_UINT32);
            vkCmdDrawIndexed(cmd, d.indexCount, 1, 0, 0, 0);
        }
        target.end(cmd);
    });
    return target.readImage8();
}

}  // namespace prism::render
