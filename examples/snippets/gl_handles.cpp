// The usage example of prism/gl/handles.hpp, compiled and run by tests/snippets.
#include <cstddef>
#include <cstdint>

// [snippet]
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/gl/handles.hpp"
// [/snippet]

// Returns how many buffers were alive inside; all are deleted when it returns.
static std::uint64_t example() {
    // [snippet]
    auto context = prism::gl::createContext();
    prism::gl::Buffer buffer = prism::gl::Buffer::create();  // glGenBuffers
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    prism::gl::VertexArray vao = prism::gl::VertexArray::create();
    float corners[] = {0.f, 0.f, 1.f, 0.f, 0.f, 1.f};
    auto vertices = prism::gl::Buffer::create(sizeof corners, GL_STATIC_DRAW, corners);  // with storage
    std::size_t bytes = vertices.bytes();                                                // 24
    auto live = prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer);           // >= 2
    // leaving the scope deletes all three names (glDeleteBuffers, glDeleteVertexArrays)
    // [/snippet]
    return bytes == sizeof(float) * 6 ? live : 0;
}

int main() {
    const std::uint64_t inside = example();
    return inside >= 1 && prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer) == 0 ? 0 : 1;
}
