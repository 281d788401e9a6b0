// The usage example of prism/vk/uniform_block.hpp, compiled and run by tests/snippets.
#include <cstring>

// [snippet]
#include "prism/vk/uniform_block.hpp"
#include "prism/shaders.hpp"  // generated catalogue, built with TARGETS gl spirv
// [/snippet]

int main() {
    // [snippet]
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const prism::catalog::Resource& block = phong.variants[0].resources[0];  // gl_DefaultUniformBlock
    prism::vk::UniformBlock uniforms(block, "phong");
    uniforms.set("u_shininess", 32.0f);                             // at u_shininess's offset
    uniforms.set(prism::shaders::contract::u_color, glm::vec4(1));  // typed handle
    std::span<const std::byte> bytes = uniforms.bytes();            // block.size bytes
    // [/snippet]
    for (const auto& m : block.members) {
        if (m.name != "u_shininess") continue;
        float v = 0;
        std::memcpy(&v, bytes.data() + m.offset, sizeof v);
        return v == 32.0f && bytes.size() == block.size ? 0 : 1;
    }
    return 1;
}
