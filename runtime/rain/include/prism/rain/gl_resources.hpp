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

class GlBuffer {
  public:
    GlBuffer() = default;
    explicit GlBuffer(std::size_t bytes, const void* data = nullptr, unsigned usage = 0x88E8 /* GL_DYNAMIC_DRAW */);
    ~GlBuffer() { release(); }
    GlBuffer(GlBuffer&& o) noexcept : id_(o.id_), bytes_(o.bytes_) {
        o.id_ = 0;
        o.bytes_ = 0;
    }
    GlBuffer& operator=(GlBuffer&& o) noexcept;
    GlBuffer(const GlBuffer&) = delete;
    GlBuffer& operator=(const GlBuffer&) = delete;
    unsigned id() const { return id_; }
    std::size_t bytes() const { return bytes_; }
    explicit operator bool() const { return id_ != 0; }

  private:
    void release() noexcept;
    unsigned id_ = 0;
    std::size_t bytes_ = 0;
};

class GlTexture {
  public:
    GlTexture();  // creates the name
    ~GlTexture() { release(); }
    GlTexture(GlTexture&& o) noexcept : id_(o.id_) { o.id_ = 0; }
    GlTexture& operator=(GlTexture&& o) noexcept;
    GlTexture(const GlTexture&) = delete;
    GlTexture& operator=(const GlTexture&) = delete;
    unsigned id() const { return id_; }

  private:
    void release() noexcept;
    unsigned id_ = 0;
};

class GlVertexArray {
  public:
    GlVertexArray();
    ~GlVertexArray() { release(); }
    GlVertexArray(GlVertexArray&& o) noexcept : id_(o.id_) { o.id_ = 0; }
    GlVertexArray& operator=(GlVertexArray&& o) noexcept;
    GlVertexArray(const GlVertexArray&) = delete;
    GlVertexArray& operator=(const GlVertexArray&) = delete;
    unsigned id() const { return id_; }

  private:
    void release() noexcept;
    unsigned id_ = 0;
};

// Uploads an R8 2D texture array (linear filtering, clamped or repeated).
GlTexture uploadR8TextureArray(int width, int height, int layers, const std::uint8_t* texels, bool repeat);

}  // namespace prism::rain
