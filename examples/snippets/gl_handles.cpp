// The usage example of prism/gl/handles.hpp, compiled and run by tests/snippets.
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
    prism::gl::Buffer buffer = prism::gl::Buffer::create();   // glGenBuffers
    glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
    prism::gl::VertexArray vao = prism::gl::VertexArray::create();
    auto live = prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer);  // >= 1
    // leaving the scope deletes both names (glDeleteBuffers, glDeleteVertexArrays)
    // [/snippet]
    return live;
}

int main() {
    const std::uint64_t inside = example();
    return inside >= 1 && prism::gl::objectCounts().live(prism::gl::ObjectKind::Buffer) == 0 ? 0 : 1;
}
