// Catalogue renders through Vulkan (prism::vk) from the catalogue's SPIR-V: the same
// framing, variant choice and frame uniforms as the GL renders of
// prism/render/offscreen_render.hpp, so the two APIs can be compared pixel by pixel.
//
// Usage (snippet: examples/snippets/render_vulkan_render.cpp):
//
//     #include "prism/render/shader_meshes.hpp"
//     #include "prism/render/vulkan_render.hpp"
//     #include "prism/shaders.hpp"
//     prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog, {.device = {.validation = true}});
//     prism::render::RenderJob job;  // as for renderImage8: shader, variant, mesh, lights, size
//     job.shader = "phong";
//     job.mesh = prism::render::meshForShader("phong", prism::render::namedMesh("torus"));
//     prism::image::Image8 image = vulkan.render(job);
//     std::size_t messages = vulkan.device().validationMessages().size();  // 0
//
// A VulkanFrame draws several objects under one camera, lights and fog (prism-render's
// --backend vulkan scenes). Each draw runs the variant its lights and fog ask for
// (prism/render/feature_variants.hpp), its uniforms filled by name from the variant's
// reflection (setFrameUniforms). Pipelines are kept per variant. No GL context is needed.
// A draw may name another catalogue (a system's, e.g. the diffraction catalogue) and carry
// VulkanDrawExtras: the system's own uniforms and textures, set by name and bound at the
// set and binding the variant's reflection gives.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "prism/render/offscreen_render.hpp"
#include "prism/render/program_cache.hpp"
#include "prism/vk/clip_convention.hpp"
#include "prism/vk/device.hpp"
#include "prism/vk/pipeline.hpp"
#include "prism/vk/texture.hpp"
#include "prism/vk/uniform_block.hpp"

namespace prism::render {

// What a system adds to a draw beyond the frame uniforms (its lookup tables, its own
// uniforms), held on the CPU. apply() runs once per draw while the frame is prepared, after
// setFrameUniforms: it sets its uniforms by name, makes its textures on the renderer's device
// and binds them; it returns them, and the renderer keeps them until the frame is read back
// (so no Vulkan object outlives the renderer's device).
class VulkanDrawExtras {
  public:
    virtual ~VulkanDrawExtras() = default;
    virtual std::vector<vk::Texture> apply(const vk::Device& device, const vk::Pipeline& pipeline,
                                           vk::UniformBlock& uniforms, vk::DescriptorSets& sets) const = 0;
};

// One object of a frame: its catalogue shader, variant overrides, mesh (prepared with
// meshForShader()), world matrix and material.
struct VulkanDraw {
    std::string shader = "phong";
    VariantValues variant;
    geometry::Mesh mesh;
    glm::mat4 world{1.0f};
    view::Material material;
    const catalog::Catalog* catalog = nullptr;  // the shader's catalogue; nullptr: the renderer's
    std::shared_ptr<VulkanDrawExtras> extras;   // nullptr: frame uniforms only
};

struct VulkanFrame {
    view::Camera camera = defaultCamera();
    view::Lights lights = defaultLights();
    std::optional<view::Fog> fog;
    int width = 512;
    int height = 512;
    glm::vec4 background{0.05f, 0.06f, 0.08f, 1.0f};
    std::vector<VulkanDraw> draws;
};

// The job as a one-draw frame, and one draw of a frame as a job (for GL's drawJob).
VulkanFrame frameOf(const RenderJob& job);
RenderJob jobOf(const VulkanFrame& frame, const VulkanDraw& draw);

struct VulkanRenderOptions {
    vk::DeviceOptions device;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;  // none, as Prism's GL renders draw both faces
    // Faults the agreement tests inject to show they bite; leave them as they are.
    vk::ClipConvention clip;
    int uniformOffsetFault = 0;  // bytes added to every uniform member's offset
};

class VulkanRenderer {
  public:
    explicit VulkanRenderer(const catalog::Catalog& catalog, VulkanRenderOptions options = {});
    ~VulkanRenderer();

    image::Image8 render(const RenderJob& job) { return render(frameOf(job)); }
    image::Image8 render(const VulkanFrame& frame);

    const vk::Device& device() const { return device_; }
    std::size_t pipelineCount() const { return pipelines_.size(); }

  private:
    struct DrawResources;
    const vk::Pipeline& pipelineFor(const catalog::Variant& variant, const std::string& label,
                                    const vk::RenderTarget& target);
    ProgramCache& variantsOf(const catalog::Catalog* catalog);
    DrawResources prepare(const VulkanFrame& frame, const VulkanDraw& draw, const vk::RenderTarget& target);

    ProgramCache variants_;  // its variant lookup only: no GL program is built
    std::map<const catalog::Catalog*, std::unique_ptr<ProgramCache>> otherCatalogs_;  // the draws' own
    VulkanRenderOptions options_;
    vk::Device device_;
    std::map<const catalog::Variant*, std::unique_ptr<vk::Pipeline>> pipelines_;
};

}  // namespace prism::render
