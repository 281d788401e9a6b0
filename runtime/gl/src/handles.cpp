// Creation, deletion and counting of GL object names (see prism/gl/handles.hpp).
#include "prism/gl/handles.hpp"

#include <string>

#include "prism/gl/gl.hpp"

namespace prism::gl {
namespace {

counters::ObjectCounters<ObjectKind> g_counters;

const char* kindName(ObjectKind kind) {
    constexpr const char* names[] = {"buffer",       "texture", "vertex array", "framebuffer",
                                     "renderbuffer", "shader",  "program",      "query"};
    return names[static_cast<int>(kind)];
}

}  // namespace

ObjectCounts objectCounts() {
    return g_counters.counts();
}

unsigned detail::createObject(ObjectKind kind, unsigned shaderType) {
    GLuint id = 0;
    switch (kind) {
        case ObjectKind::Buffer: glGenBuffers(1, &id); break;
        case ObjectKind::Texture: glGenTextures(1, &id); break;
        case ObjectKind::VertexArray: glGenVertexArrays(1, &id); break;
        case ObjectKind::Framebuffer: glGenFramebuffers(1, &id); break;
        case ObjectKind::Renderbuffer: glGenRenderbuffers(1, &id); break;
        case ObjectKind::Shader: id = glCreateShader(shaderType); break;
        case ObjectKind::Program: id = glCreateProgram(); break;
        case ObjectKind::Query: glGenQueries(1, &id); break;
        case ObjectKind::Count: break;
    }
    if (id == 0) throw GlError(std::string("GL could not create a ") + kindName(kind) + " (is a context current?)");
    g_counters.created(kind);
    return id;
}

Buffer Buffer::create(std::size_t bytes, unsigned usage, const void* data) {
    Buffer buffer(detail::createObject(ObjectKind::Buffer, 0), bytes);
    // The copy-write target: binding it disturbs no vertex, index or storage binding.
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer.id());
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    throwIfGlError("allocating a GL buffer of " + std::to_string(bytes) + " bytes");
    return buffer;
}

void detail::deleteObject(ObjectKind kind, unsigned id) noexcept {
    GLuint name = id;
    switch (kind) {
        case ObjectKind::Buffer: glDeleteBuffers(1, &name); break;
        case ObjectKind::Texture: glDeleteTextures(1, &name); break;
        case ObjectKind::VertexArray: glDeleteVertexArrays(1, &name); break;
        case ObjectKind::Framebuffer: glDeleteFramebuffers(1, &name); break;
        case ObjectKind::Renderbuffer: glDeleteRenderbuffers(1, &name); break;
        case ObjectKind::Shader: glDeleteShader(name); break;
        case ObjectKind::Program: glDeleteProgram(name); break;
        case ObjectKind::Query: glDeleteQueries(1, &name); break;
        case ObjectKind::Count: break;
    }
    g_counters.destroyed(kind);
}

}  // namespace prism::gl
