// docs/vulkan.md's walk-through, compiled and run by tests/snippets: one catalogue program
// drawn with prism::vk alone, from the catalogue's SPIR-V and reflection.
#include <glm/gtc/matrix_transform.hpp>

#include "prism/geometry/procedural_meshes.hpp"
// [snippet]
#include "prism/shaders.hpp"  // the catalogue, built with TARGETS gl es300 spirv
#include "prism/vk/pipeline.hpp"
#include "prism/vk/render_target.hpp"
#include "prism/vk/uniform_block.hpp"
// [/snippet]

int main() {
    const prism::geometry::Mesh mesh = prism::geometry::makeIcosphere(1.0f, 2);
    // [snippet]
    // 1. A device (validation on) and an off-screen RGBA8 + depth target.
    prism::vk::Device device({.validation = true});
    prism::vk::RenderTarget target(device, 128, 128);

    // 2. The variant's pipeline: its SPIR-V, descriptor layouts and vertex inputs from the catalogue.
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const auto* variant = prism::catalog::findVariant(phong, {{"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "0"}});
    if (variant == nullptr) return 1;
    const prism::vk::VertexStream streams[] = {{"a_position", VK_FORMAT_R32G32B32_SFLOAT, 12},
                                               {"a_normal", VK_FORMAT_R32G32B32_SFLOAT, 12}};
    prism::vk::Pipeline pipeline(device, target, *variant, streams, {.label = "phong"});

    // 3. The loose uniforms, packed by the spirv target into gl_DefaultUniformBlock: by name.
    prism::vk::UniformBlock block(*pipeline.uniformBlock(), "phong");
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 3), glm::vec3(0), glm::vec3(0, 1, 0));
    block.set("u_world", glm::mat4(1.0f));
    block.set("u_view", view);
    block.set("u_projection", glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 50.0f));  // GL's, unchanged
    block.set("u_normal", glm::mat3(view));
    block.set("u_color", glm::vec4(0.8f, 0.35f, 0.25f, 1.0f));
    block.set("u_ambient", glm::vec3(0.1f));
    block.set("u_directionalLightCount", 1);
    block.set("u_lightDirection[0]", glm::vec3(-0.5f, -0.6f, -0.65f));
    block.set("u_lightColor[0]", glm::vec3(0.9f));
    prism::vk::Buffer uniforms(device, block.bytes().size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    uniforms.write(block.bytes().data(), block.bytes().size());
    prism::vk::DescriptorSets sets(device, pipeline);
    sets.bindBuffer(*pipeline.uniformBlock(), uniforms);

    // 4. Vertex and index buffers.
    auto upload = [&](const auto& data, VkBufferUsageFlags usage) {
        prism::vk::Buffer b(device, data.size() * sizeof data[0], usage);
        b.write(data.data(), data.size() * sizeof data[0]);
        return b;
    };
    const auto positions = upload(mesh.positions, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    const auto normals = upload(mesh.normals, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    const auto indices = upload(mesh.indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

    // 5. Record, submit, wait, read back: row 0 is the top row, as in GL's read-back after its flip.
    device.submit([&](VkCommandBuffer cmd) {
        target.begin(cmd, {0.05f, 0.06f, 0.08f, 1.0f});
        pipeline.bind(cmd, target.width(), target.height());  // GL's clip conventions (clip_convention.hpp)
        sets.bind(cmd, pipeline);
        const VkBuffer vertexBuffers[] = {positions.get(), normals.get()};
        const VkDeviceSize offsets[] = {0, 0};
        vkCmdBindVertexBuffers(cmd, 0, 2, vertexBuffers, offsets);
        vkCmdBindIndexBuffer(cmd, indices.get(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, static_cast<std::uint32_t>(mesh.indices.size()), 1, 0, 0, 0);
        target.end(cmd);
    });
    prism::image::Image8 image = target.readImage8();
    // [/snippet]
    const bool lit = image.at(64, 64)[0] > 40 && image.at(2, 2) == prism::image::Rgba8{13, 15, 20, 255};
    return lit && device.validationMessages().empty() ? 0 : 1;
}
