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
//     prism::gl::Buffer buffer = prism::gl::Buffer::create();   // glGenBuffers
//     glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
//     prism::gl::VertexArray vao = prism::gl::VertexArray::create();
//     auto live = prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer);  // >= 1
//     // leaving the scope deletes both names (glDeleteBuffers, glDeleteVertexArrays)
//
// A default-constructed handle owns nothing (id() == 0). Needs a current context when a
// name is created or deleted.
#pragma once

#include <array>
#include <cstdint>
#include <utility>

namespace prism::gl {

enum class ObjectKind : int { Buffer, Texture, VertexArray, Framebuffer, Renderbuffer, Shader, Program, Query, Count };

// Objects created since start-up and alive now, per kind.
struct ObjectCounts {
    std::array<std::uint64_t, static_cast<int>(ObjectKind::Count)> createdByKind{}, liveByKind{};
    std::uint64_t created(ObjectKind kind) const { return createdByKind[static_cast<int>(kind)]; }
    std::uint64_t live(ObjectKind kind) const { return liveByKind[static_cast<int>(kind)]; }
};
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

using Buffer = Handle<ObjectKind::Buffer>;
using Texture = Handle<ObjectKind::Texture>;
using VertexArray = Handle<ObjectKind::VertexArray>;
using FramebufferObject = Handle<ObjectKind::Framebuffer>;
using Renderbuffer = Handle<ObjectKind::Renderbuffer>;
using ProgramObject = Handle<ObjectKind::Program>;
using Query = Handle<ObjectKind::Query>;

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
