// The Vulkan side of the diffraction shader: one path's lookup tables (built on the CPU,
// lookup_tables.hpp) as Vulkan images with GL's filtering, bound at the set and binding of the
// diffraction catalogue's SPIR-V reflection, and modules/diffraction/stam.glsl's uniforms
// set by name in the draw's uniform block. A draw's extras (prism/render/vulkan_render.hpp).
//
// Usage (snippet: examples/snippets/diffraction_diffraction_vk.cpp):
//
//     #include "prism/diffraction/diffraction_vk.hpp"
//     #include "prism/diffraction_shaders.hpp"
//     #include "prism/render/shader_meshes.hpp"
//     using namespace prism::diffraction;
//     StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
//     MaterialTables tables;
//     tables.integrated = buildIntegratedTables(buildSpectralTables(brdf, {.size = 32}));  // path (b)
//     prism::render::VulkanDraw draw;
//     draw.shader = "diffraction";
//     draw.catalog = &prism::diffraction_shaders::kCatalog;
//     draw.extras = std::make_shared<VulkanDiffractionTables>(std::move(tables));
//     draw.variant = {{"DIFFRACTION_PATH", "1"}};
//     draw.mesh = prism::render::meshForShader("diffraction", prism::render::namedMesh("grid", 2));
//     prism::render::VulkanFrame frame;
//     frame.draws.push_back(std::move(draw));
//     prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
//     prism::image::Image8 image = vulkan.render(frame);
//
// The images are made for each draw on the renderer's device, which keeps them until the
// frame is read back; the CPU tables stay here, shared by the draws. Paths b and c's RGB
// tables are uploaded as RGBA32F (Vulkan need not sample RGB32F), path a's as RG32F with its
// wavelengths as one RGBA32F row (nearest, as GL's).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "prism/diffraction/material.hpp"
#include "prism/render/vulkan_render.hpp"
#include "prism/vk/texture.hpp"

namespace prism::diffraction {

class VulkanDiffractionTables : public render::VulkanDrawExtras {
  public:
    // `tangent` and `radial` are the material's (u_diffractionTangent, u_diffractionRadial).
    explicit VulkanDiffractionTables(MaterialTables tables, std::array<double, 3> tangent = {1.0, 0.0, 0.0},
                                     bool radial = false);

    const TableUniforms& uniforms() const { return uniforms_; }
    std::vector<vk::Texture> apply(const vk::Device& device, const vk::Pipeline& pipeline, vk::UniformBlock& uniforms,
                                   vk::DescriptorSets& sets) const override;

    // A fault the agreement tests inject to show they catch it: the tables sampled nearest
    // instead of GL's linear filtering. Leave it false.
    bool nearestFilterFault = false;

  private:
    // The lookup image (and path a's wavelength row second), with GL's filtering.
    std::vector<vk::Texture> upload(const vk::Device& device) const;

    MaterialTables tables_;
    TableUniforms uniforms_;
    std::array<double, 3> tangent_;
    bool radial_;
};

}  // namespace prism::diffraction
