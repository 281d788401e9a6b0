// Counted owners of the rain code's GL objects (see prism/rain/gl_resources.hpp).
#include "prism/rain/gl_resources.hpp"

#include <atomic>

#include "prism/gl/gl.hpp"

namespace prism::rain {
namespace {

struct Counters {
    std::atomic<std::uint64_t> buffersCreated{0}, buffersLive{0};
    std::atomic<std::uint64_t> texturesCreated{0}, texturesLive{0};
    std::atomic<std::uint64_t> vertexArraysCreated{0}, vertexArraysLive{0};
    std::atomic<std::uint64_t> bufferBytesLive{0};
    std::atomic<std::uint64_t> computeDispatches{0};
};

Counters& counters() {
    static Counters c;
    return c;
}

}  // namespace

GlObjectCounts glObjectCounts() {
    const Counters& c = counters();
    GlObjectCounts r;
    r.buffersCreated = c.buffersCreated;
    r.buffersLive = c.buffersLive;
    r.texturesCreated = c.texturesCreated;
    r.texturesLive = c.texturesLive;
    r.vertexArraysCreated = c.vertexArraysCreated;
    r.vertexArraysLive = c.vertexArraysLive;
    r.bufferBytesLive = c.bufferBytesLive;
    r.computeDispatches = c.computeDispatches;
    return r;
}

void detail::countDispatch() {
    ++counters().computeDispatches;
}

GlBuffer::GlBuffer(std::size_t bytes, const void* data, unsigned usage)
    : buffer_(gl::Buffer::create()), bytes_(bytes) {
    ++counters().buffersCreated;
    ++counters().buffersLive;
    counters().bufferBytesLive += bytes;
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer_.id());
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    if (glGetError() == GL_OUT_OF_MEMORY) {
        release();
        throw gl::GlError("rain: out of GL memory allocating a buffer of " + std::to_string(bytes) + " bytes");
    }
}

GlBuffer& GlBuffer::operator=(GlBuffer&& o) noexcept {
    if (this != &o) {
        release();
        buffer_ = std::move(o.buffer_);
        bytes_ = std::exchange(o.bytes_, 0);
    }
    return *this;
}

void GlBuffer::release() noexcept {
    if (!buffer_) return;
    buffer_.reset();
    --counters().buffersLive;
    counters().bufferBytesLive -= bytes_;
    bytes_ = 0;
}

GlTexture::GlTexture() : texture_(gl::Texture::create()) {
    ++counters().texturesCreated;
    ++counters().texturesLive;
}

GlTexture& GlTexture::operator=(GlTexture&& o) noexcept {
    if (this != &o) {
        release();
        texture_ = std::move(o.texture_);
    }
    return *this;
}

void GlTexture::release() noexcept {
    if (!texture_) return;
    texture_.reset();
    --counters().texturesLive;
}

GlVertexArray::GlVertexArray() : vertexArray_(gl::VertexArray::create()) {
    ++counters().vertexArraysCreated;
    ++counters().vertexArraysLive;
}

GlVertexArray& GlVertexArray::operator=(GlVertexArray&& o) noexcept {
    if (this != &o) {
        release();
        vertexArray_ = std::move(o.vertexArray_);
    }
    return *this;
}

void GlVertexArray::release() noexcept {
    if (!vertexArray_) return;
    vertexArray_.reset();
    --counters().vertexArraysLive;
}

GlTexture uploadR8TextureArray(int width, int height, int layers, const std::uint8_t* texels, bool repeat) {
    GlTexture texture;
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_R8, width, height, layers, 0, GL_RED, GL_UNSIGNED_BYTE, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, wrap);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    gl::throwIfGlError("rain: uploading a texture array");
    return texture;
}

}  // namespace prism::rain
