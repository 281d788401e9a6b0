// GL objects created by prism_rain, counted, so tests can show that a scene without
// rain creates no particle buffers and runs no rain update (RainScene adds the program
// list). Every buffer, texture and vertex array of the rain code goes through these
// move-only owners; the counters are process-wide.
//
// Usage (snippet: examples/snippets/rain_gl_resources.cpp):
//
//     #include "prism/rain/gl_resources.hpp"
//     auto before = prism::rain::glObjectCounts();
//     // ... build and render a scene ...
//     auto after = prism::rain::glObjectCounts();
//     std::uint64_t made = after.buffersCreated - before.buffersCreated;   // buffers the rain code made
//
// Needs a current context while objects are created or destroyed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

#include "prism/gl/handles.hpp"

namespace prism::rain {

struct GlObjectCounts {
    std::uint64_t buffersCreated = 0, buffersLive = 0;
    std::uint64_t texturesCreated = 0, texturesLive = 0;
    std::uint64_t vertexArraysCreated = 0, vertexArraysLive = 0;
    std::uint64_t bufferBytesLive = 0;    // bytes of live buffers (particles, billboards)
    std::uint64_t computeDispatches = 0;  // rain_init and rain_update dispatches
};
GlObjectCounts glObjectCounts();

namespace detail {
void countDispatch();
}

// Rain's buffers, textures and vertex arrays: prism::gl handles (prism/gl/handles.hpp)
// that also count themselves in glObjectCounts(). Move-only.
class GlBuffer {
  public:
    GlBuffer() = default;  // owns nothing
    explicit GlBuffer(std::size_t bytes, const void* data = nullptr, unsigned usage = 0x88E8 /* GL_DYNAMIC_DRAW */);
    ~GlBuffer() { release(); }
    GlBuffer(GlBuffer&& o) noexcept : buffer_(std::move(o.buffer_)), bytes_(std::exchange(o.bytes_, 0)) {}
    GlBuffer& operator=(GlBuffer&& o) noexcept;
    unsigned id() const { return buffer_.id(); }
    std::size_t bytes() const { return bytes_; }
    explicit operator bool() const { return static_cast<bool>(buffer_); }

  private:
    void release() noexcept;
    gl::Buffer buffer_;
    std::size_t bytes_ = 0;
};

class GlTexture {
  public:
    GlTexture();  // creates the name
    ~GlTexture() { release(); }
    GlTexture(GlTexture&& o) noexcept = default;
    GlTexture& operator=(GlTexture&& o) noexcept;
    unsigned id() const { return texture_.id(); }

  private:
    void release() noexcept;
    gl::Texture texture_;
};

class GlVertexArray {
  public:
    GlVertexArray();  // creates the name
    ~GlVertexArray() { release(); }
    GlVertexArray(GlVertexArray&& o) noexcept = default;
    GlVertexArray& operator=(GlVertexArray&& o) noexcept;
    unsigned id() const { return vertexArray_.id(); }

  private:
    void release() noexcept;
    gl::VertexArray vertexArray_;
};

// Uploads an R8 2D texture array (linear filtering, clamped or repeated).
GlTexture uploadR8TextureArray(int width, int height, int layers, const std::uint8_t* texels, bool repeat);

}  // namespace prism::rain
