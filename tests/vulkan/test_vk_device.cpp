// prism::vk's objects: nothing leaks, the validation layer is on and its messenger counts
// what it reports, and a machine without a Vulkan driver gets an error naming the package.
#include <gtest/gtest.h>

#include "prism/render/shader_meshes.hpp"
#include "prism/scene/vulkan_scene.hpp"
#include "prism/shaders.hpp"
#include "prism/test/run_command.hpp"
#include "prism/vk/buffer.hpp"
#include "vulkan_test_support.hpp"

namespace prism::vulkan_test {
namespace {

TEST(VulkanObjects, NothingLeaksAfterRendersOfSeveralDraws) {
    const vk::ObjectCounts before = vk::objectCounts();
    {
        render::VulkanRenderer vulkan(shaders::kCatalog, {.device = {true}});
        render::RenderJob job;
        job.width = job.height = 32;
        job.mesh = render::meshForShader("phong", render::namedMesh("torus", 1));
        (void)vulkan.render(job);
        render::VulkanFrame frame = render::frameOf(job);
        frame.draws.push_back(
            {"flat", {}, render::meshForShader("flat", render::namedMesh("cube")), {}, {}, nullptr, nullptr});
        (void)vulkan.render(frame);
        EXPECT_EQ(vulkan.pipelineCount(), 2u);
        // Textures, samplers and an RGBA32F target: the soft shadows' frames (two, sorted).
        scene::StochasticSettings soft;
        soft.sampler = bluenoise::SamplerKind::Sorted;
        soft.frames = 2;
        soft.maskSize = 16;
        (void)scene::renderStochasticVulkan(soft, 24, 16, vulkan.device());
        expectNoValidationMessages(vulkan);
    }
    const vk::ObjectCounts after = vk::objectCounts();
    for (int k = 0; k < static_cast<int>(vk::ObjectKind::Count); ++k) {
        const auto kind = static_cast<vk::ObjectKind>(k);
        EXPECT_EQ(after.live(kind), before.live(kind)) << "object kind " << k << " leaked";
    }
    // Every kind a render needs was made (and so counted) at least once.
    for (auto kind : {vk::ObjectKind::Instance, vk::ObjectKind::Device, vk::ObjectKind::Buffer, vk::ObjectKind::Image,
                      vk::ObjectKind::ImageView, vk::ObjectKind::Sampler, vk::ObjectKind::Pipeline,
                      vk::ObjectKind::DescriptorPool, vk::ObjectKind::Fence})
        EXPECT_GT(after.created(kind), before.created(kind)) << "object kind " << static_cast<int>(kind);
}

// The messenger records what the layer reports: an invalid call (a buffer of 0 bytes, which
// Vulkan forbids) is one message. So the zero asserted elsewhere is a real zero.
TEST(VulkanObjects, TheValidationMessengerCountsAnInvalidCall) {
    vk::Device device({.validation = true});
    ASSERT_TRUE(device.validationMessages().empty());
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (vkCreateBuffer(device.device(), &info, nullptr, &buffer) == VK_SUCCESS)
        vkDestroyBuffer(device.device(), buffer, nullptr);
    const auto messages = device.validationMessages();
    ASSERT_FALSE(messages.empty());
    EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-size"), std::string::npos) << messages.front();
}

// VK_ICD_FILENAMES (and VK_DRIVER_FILES, its newer name) at a file that does not exist: the
// loader finds no driver, as on a machine without mesa-vulkan-drivers.
TEST(VulkanObjects, NoDriverSaysWhatToInstall) {
    const auto r = test::runCommand({"/usr/bin/env", "VK_ICD_FILENAMES=/nonexistent/icd.json",
                                     "VK_DRIVER_FILES=/nonexistent/icd.json", PRISM_RENDER_EXECUTABLE, "--backend",
                                     "vulkan", "--shader", "phong", "--out", PRISM_VULKAN_OUT "/no-driver.png"});
    EXPECT_EQ(r.exitCode, 1) << r;
    EXPECT_NE(r.err.find("install mesa-vulkan-drivers"), std::string::npos) << r;
    EXPECT_FALSE(std::filesystem::exists(PRISM_VULKAN_OUT "/no-driver.png"));
}

}  // namespace
}  // namespace prism::vulkan_test
