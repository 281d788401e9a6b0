// The GL state a draw may change and the next draw assumes: capabilities (blend, depth
// test, culling, point size, seamless cube maps), blend factors and equations, depth mask
// and function, colour mask, program, vertex array and its attribute arrays, buffer
// bindings (array, storage, uniform, pixel, copy, indirect), textures and samplers on the
// first units, the active unit, framebuffers, viewport and pixel-store alignment.
// DrawState::capture() reads it with glGet; ScopedDrawState puts it back when a system's
// draw returns, so one system cannot leave, say, blending or a bound texture array to the
// next (docs/gpu.md).
//
// Usage (snippet: examples/snippets/gl_draw_state.cpp):
//
//     #include "prism/gl/draw_state.hpp"
//     prism::gl::DrawState before = prism::gl::DrawState::capture();
//     {
//         prism::gl::ScopedDrawState keep;  // restored when the scope ends
//         glEnable(GL_BLEND);
//     }
//     std::string changed = prism::gl::describeChanges(before, prism::gl::DrawState::capture());  // ""
//
// Needs a current context.
#pragma once

#include <array>
#include <string>

namespace prism::gl {

struct DrawState {
    static constexpr int kTextureUnits = 16;   // units checked and restored
    static constexpr int kAttributes = 16;     // vertex attribute arrays of the bound VAO
    static constexpr int kIndexedBuffers = 8;  // storage and uniform buffer binding points
    static constexpr int kTextureTargets = 5;  // 2D, 2D array, cube map, 3D, buffer

    std::array<int, 8> enabled{};  // the capabilities of kCapabilities, in order
    std::array<int, 6> blend{};    // src/dst RGB, src/dst alpha, equation RGB/alpha
    std::array<int, 4> colorMask{};
    int depthMask = 0, depthFunc = 0;
    int program = 0, vertexArray = 0;
    std::array<int, kAttributes> attributeEnabled{};  // of the bound vertex array (0: none)
    std::array<int, 8> buffers{};  // array, storage, uniform, pixel pack/unpack, copy read/write, indirect
    int elementBuffer = 0;         // of the bound vertex array
    std::array<int, kIndexedBuffers> storageBuffers{}, uniformBuffers{};
    int activeTexture = 0;
    std::array<std::array<int, kTextureTargets>, kTextureUnits> textures{};
    std::array<int, kTextureUnits> samplers{};
    int drawFramebuffer = 0, readFramebuffer = 0;
    std::array<int, 4> viewport{};
    int unpackAlignment = 0, packAlignment = 0;

    static DrawState capture();
    void restore() const;
    bool operator==(const DrawState&) const = default;
};

// "blend: 0 -> 1; texture unit 3 2D array: 0 -> 7; ..." for every field that differs; "" when equal.
std::string describeChanges(const DrawState& before, const DrawState& after);

// Captures on construction, restores on destruction.
class ScopedDrawState {
  public:
    ScopedDrawState() : saved_(DrawState::capture()) {}
    ~ScopedDrawState() { saved_.restore(); }
    ScopedDrawState(const ScopedDrawState&) = delete;
    ScopedDrawState& operator=(const ScopedDrawState&) = delete;

  private:
    DrawState saved_;
};

}  // namespace prism::gl
