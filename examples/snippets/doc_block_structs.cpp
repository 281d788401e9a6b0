// docs/vulkan.md, "Block structs": a Vulkan-client catalogue's generated block struct and the
// reflection fields, on the catalogue tests/shaderc builds from vk_reflection_layouts.
// [snippet]
#include "prism_vulkan_test_shaders.hpp"  // a catalogue built with prism_add_shaders(... CLIENT vulkan)
// [/snippet]

int main() {
    // [snippet]
    namespace shaders = prism_test::vulkan_shaders;
    shaders::blocks::layouts::Push push{};  // layouts.vert's `layout(push_constant) uniform Push`
    push.model = glm::mat4(1.0f);
    push.vertices = 0x10000;  // a buffer_reference: the VkDeviceAddress, 8 bytes
    push.materialIndex = 3;
    static_assert(sizeof(push) == 80);  // what vkCmdPushConstants gets; a drifted layout fails to compile

    const auto& v = shaders::shaderInfo(shaders::ShaderId::layouts).variants[0];
    const prism::catalog::Resource& textures = v.resources[0];  // set 0, binding 0: `textures[]`
    const bool bindless = textures.arraySize == prism::catalog::kUnboundedArray;
    const prism::catalog::Resource& materials = v.resources[1];  // a storage block ending in `float factors[]`
    const std::size_t bytesFor100 = materials.size + 100 * materials.runtimeStride;
    const bool unusedListed = !v.resources[2].used;  // declared, never read: the set layout still needs it
    // [/snippet]
    return bindless && bytesFor100 == 432 && unusedListed && push.materialIndex == 3 ? 0 : 1;
}
