// Move-only owners of GL object names, one type per object kind, and process-wide
// counters of the objects created and alive (for leak checks and for tests that show a
// feature created nothing). Every GL object in Prism is owned through these.
//
// Usage (snippet: examples/snippets/gl_handles.cpp):
//
//     #include "prism/gl/gl.hpp"
//     #include "prism/gl/gl_context.hpp"
//     #include "prism/gl/handles.hpp"
//     auto context = prism::gl::createContext();
//     prism::gl::Buffer buffer = prism::gl::Buffer::create();  // glGenBuffers
//     glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
//     prism::gl::VertexArray vao = prism::gl::VertexArray::create();
//     float corners[] = {0.f, 0.f, 1.f, 0.f, 0.f, 1.f};
//     auto vertices = prism::gl::Buffer::create(sizeof corners, GL_STATIC_DRAW, corners);  // with storage
//     std::size_t bytes = vertices.bytes();                                                // 24
//     auto live = prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer);           // >= 2
//     // leaving the scope deletes all three names (glDeleteBuffers, glDeleteVertexArrays)
//
// A default-constructed handle owns nothing (id() == 0). Needs a current context when a
// name is created or deleted.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "prism/counters/object_counters.hpp"

namespace prism::gl {

enum class ObjectKind : int { Buffer, Texture, VertexArray, Framebuffer, Renderbuffer, Shader, Program, Query, Count };

// Objects created since start-up and alive now, per kind (prism/counters/object_counters.hpp).
using ObjectCounts = counters::Counts<ObjectKind>;
ObjectCounts objectCounts();

namespace detail {
unsigned createObject(ObjectKind kind, unsigned shaderType);  // shaderType only for ObjectKind::Shader
void deleteObject(ObjectKind kind, unsigned id) noexcept;
}  // namespace detail

template <ObjectKind Kind>
class Handle {
  public:
    Handle() = default;
    static Handle create() { return Handle(detail::createObject(Kind, 0)); }
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    unsigned id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    // Deletes the name now (a no-op for an empty handle).
    void reset() noexcept {
        if (id_ != 0) detail::deleteObject(Kind, std::exchange(id_, 0));
    }

  protected:
    explicit Handle(unsigned id) : id_(id) {}

  private:
    unsigned id_ = 0;
};

using Texture = Handle<ObjectKind::Texture>;
using VertexArray = Handle<ObjectKind::VertexArray>;
using FramebufferObject = Handle<ObjectKind::Framebuffer>;
using Renderbuffer = Handle<ObjectKind::Renderbuffer>;
using ProgramObject = Handle<ObjectKind::Program>;
using Query = Handle<ObjectKind::Query>;

// A buffer, and the size of the storage that create(bytes, ...) gave it (0 for a bare
// name whose owner calls glBufferData itself). Usage values are the loader's
// (GL_STATIC_DRAW, GL_DYNAMIC_DRAW ...): this header stays free of GL headers, which
// clash with <GL/gl.h> in a user's file (see prism/gl/gl.hpp).
class Buffer : public Handle<ObjectKind::Buffer> {
  public:
    Buffer() = default;
    static Buffer create() { return Buffer(detail::createObject(ObjectKind::Buffer, 0), 0); }
    // glBufferData of `bytes` (copied from `data` unless null); throws GlError naming the
    // size when GL cannot allocate it.
    static Buffer create(std::size_t bytes, unsigned usage, const void* data = nullptr);
    Buffer(Buffer&& other) noexcept : Handle(std::move(other)), bytes_(std::exchange(other.bytes_, 0)) {}
    Buffer& operator=(Buffer&& other) noexcept {
        const std::size_t bytes = std::exchange(other.bytes_, 0);
        Handle::operator=(std::move(other));
        bytes_ = bytes;
        return *this;
    }
    ~Buffer() = default;

    std::size_t bytes() const { return bytes_; }
    void reset() noexcept {
        Handle::reset();
        bytes_ = 0;
    }

  private:
    Buffer(unsigned id, std::size_t bytes) : Handle(id), bytes_(bytes) {}
    std::size_t bytes_ = 0;
};

// Shaders need their stage type (GL_VERTEX_SHADER ...) at creation.
class ShaderObject : public Handle<ObjectKind::Shader> {
  public:
    ShaderObject() = default;
    static ShaderObject create(unsigned shaderType) {
        return ShaderObject(detail::createObject(ObjectKind::Shader, shaderType));
    }

  private:
    explicit ShaderObject(unsigned id) : Handle(id) {}
};

}  // namespace prism::gl
