// The diffraction tables as Vulkan images and stam.glsl's uniforms by name (see diffraction_vk.hpp).
#include "prism/diffraction/diffraction_vk.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace prism::diffraction {
namespace {

TableUniforms uniformsOf(const MaterialTables& t) {
    if (t.spectral) return tableUniforms(*t.spectral);
    if (t.integrated) return tableUniforms(*t.integrated);
    if (t.volume) return tableUniforms(*t.volume);
    throw std::invalid_argument("prism::diffraction::VulkanDiffractionTables: the material tables hold no path");
}

vk::Texture makeTexture(const vk::Device& device, const vk::TextureDescription& description,
                        const std::vector<float>& texels) {
    return vk::Texture(device, description, texels.data(), texels.size() * sizeof(float));
}

}  // namespace

VulkanDiffractionTables::VulkanDiffractionTables(MaterialTables tables, std::array<double, 3> tangent, bool radial)
    : tables_(std::move(tables)), uniforms_(uniformsOf(tables_)), tangent_(tangent), radial_(radial) {}

// GL's texture parameters (diffraction_gl.cpp): the tables linear and clamped, the wavelengths nearest.
std::vector<vk::Texture> VulkanDiffractionTables::upload(const vk::Device& device) const {
    const VkFilter filter = nearestFilterFault ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    const int size = uniforms_.size;
    std::vector<vk::Texture> textures;
    if (tables_.spectral) {
        const SpectralTables& t = *tables_.spectral;
        textures.push_back(makeTexture(
            device, {VK_IMAGE_VIEW_TYPE_2D_ARRAY, size, size, t.terms + 1, VK_FORMAT_R32G32_SFLOAT, filter}, t.texels));
        textures.push_back(makeTexture(
            device,
            {VK_IMAGE_VIEW_TYPE_2D, uniforms_.wavelengthCount, 1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, VK_FILTER_NEAREST},
            wavelengthTexels(t)));
    } else if (tables_.integrated) {
        const IntegratedTables& t = *tables_.integrated;
        textures.push_back(makeTexture(
            device, {VK_IMAGE_VIEW_TYPE_2D_ARRAY, size, size, 2 * t.terms + 1, VK_FORMAT_R32G32B32A32_SFLOAT, filter},
            rgbaTexels(t.texels)));
    } else {
        const VolumeTables& t = *tables_.volume;
        textures.push_back(
            makeTexture(device, {VK_IMAGE_VIEW_TYPE_3D, size, size, t.slices, VK_FORMAT_R32G32B32A32_SFLOAT, filter},
                        rgbaTexels(t.texels)));
    }
    return textures;
}

std::vector<vk::Texture> VulkanDiffractionTables::apply(const vk::Device& device, const vk::Pipeline& pipeline,
                                                        vk::UniformBlock& block, vk::DescriptorSets& sets) const {
    std::vector<vk::Texture> textures = upload(device);
    const vk::Texture& lookup = textures.front();
    const TableUniforms& u = uniforms_;
    block.set("u_diffractionTableSize", static_cast<float>(u.size));
    block.set("u_diffractionExtent", static_cast<float>(u.extent));
    if (u.path == 2) {
        sets.bindImage(pipeline.resource("u_diffractionVolume"), lookup.view(), lookup.sampler());
        block.set("u_diffractionSlices", static_cast<float>(u.slices));
    } else {
        sets.bindImage(pipeline.resource("u_diffractionTables"), lookup.view(), lookup.sampler());
        block.set("u_diffractionTerms", u.terms);
    }
    if (u.path == 0) {
        sets.bindImage(pipeline.resource("u_diffractionWavelengths"), textures.back().view(),
                       textures.back().sampler());
        block.set("u_diffractionHeightScale", static_cast<float>(u.heightScaleNm));
        block.set("u_diffractionWavelengthCount", u.wavelengthCount);
    }
    block.set("u_diffractionTangent", glm::vec3(static_cast<float>(tangent_[0]), static_cast<float>(tangent_[1]),
                                                static_cast<float>(tangent_[2])));
    block.set("u_diffractionRadial", radial_ ? 1.0f : 0.0f);
    return textures;
}

}  // namespace prism::diffraction
