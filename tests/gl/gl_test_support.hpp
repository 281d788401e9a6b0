// Shared pieces of the GL-tier tests: a hand-written tiny shader catalogue (the
// shape prism-shaderc generates) and helpers to draw a triangle into a framebuffer.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::test {

namespace cat = prism::catalog;

// --- The catalogue -------------------------------------------------------------
// Module 0 "colors" (modules/colors.glsl): one helper function.
inline constexpr std::string_view kColorsModuleChunks[] = {
    "// colours module\n"
    "vec4 solidColor(vec4 c) { return c; }\n"};
inline constexpr cat::Module kModules[] = {
    {"colors", "modules/colors.glsl", "colour helpers", kColorsModuleChunks, {}},
};

// The contract: what the runtime supplies.
inline constexpr cat::Attribute kContractAttributes[] = {
    {"a_position", 0x8B50 /* GL_FLOAT_VEC2 */, 0},
    {"a_color", 0x8B52 /* GL_FLOAT_VEC4 */, 1},
};

// Shader "solid": a triangle in u_color, times the sum of u_weights.
inline constexpr std::string_view kSolidVert[] = {
    "#version 330 core\n"
    "in vec2 a_position;\n"
    "void main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n"};
inline constexpr cat::SourceFile kSolidVertFiles[] = {{0, "shaders/solid.vert"}};

// As the tool emits it: the module's text under `#line 1 1`, the stage file resumed
// with `#line 3 0` after its `#include` on line 2.
inline constexpr std::string_view kSolidFrag[] = {
    "#version 330 core\n"
    "#line 1 1\n"
    "// colours module\n"
    "vec4 solidColor(vec4 c) { return c; }\n",
    // a second chunk, to check chunks are joined
    "#line 3 0\n"
    "uniform vec4 u_color;\n"
    "uniform float u_weights[3];\n"
    "out vec4 fragColor;\n"
    "void main() { fragColor = solidColor(u_color) * (u_weights[0] + u_weights[1] + u_weights[2]); }\n"};
inline constexpr cat::SourceFile kSolidFragFiles[] = {{0, "shaders/solid.frag"}, {1, "modules/colors.glsl"}};

inline constexpr cat::StageSource kSolidStages[] = {
    {cat::Stage::Vertex, kSolidVert, kSolidVertFiles},
    {cat::Stage::Fragment, kSolidFrag, kSolidFragFiles},
};
inline constexpr cat::Attribute kSolidAttributes[] = {{"a_position", 0x8B50, 0}};
inline constexpr cat::Uniform kSolidUniforms[] = {
    {"u_color", 0x8B52 /* GL_FLOAT_VEC4 */, 1},
    {"u_weights[0]", 0x1406 /* GL_FLOAT */, 3},
};

// Variant "BROKEN=1": line 3 of source 1 (modules/colors.glsl) uses an undeclared name.
inline constexpr std::string_view kBrokenFrag[] = {
    "#version 330 core\n"
    "#line 1 1\n"
    "// colours module\n"
    "vec4 solidColor(vec4 c) { return c; }\n"
    "vec4 broken() { return undeclared_thing; }\n"
    "#line 3 0\n"
    "out vec4 fragColor;\n"
    "void main() { fragColor = solidColor(vec4(1.0)); }\n"};
inline constexpr cat::StageSource kBrokenStages[] = {
    {cat::Stage::Vertex, kSolidVert, kSolidVertFiles},
    {cat::Stage::Fragment, kBrokenFrag, kSolidFragFiles},
};

inline constexpr std::string_view kBrokenValues[] = {"0", "1"};
inline constexpr cat::VariantAxis kSolidAxes[] = {{"BROKEN", kBrokenValues}};
inline constexpr cat::Define kDefaultDefines[] = {{"BROKEN", "0"}};
inline constexpr cat::Define kBrokenDefines[] = {{"BROKEN", "1"}};

inline constexpr cat::Variant kSolidVariants[] = {
    {"BROKEN=0", kDefaultDefines, kSolidStages, kSolidAttributes, kSolidUniforms},
    {"BROKEN=1", kBrokenDefines, kBrokenStages, kSolidAttributes, {}},
};
inline constexpr std::uint32_t kSolidModules[] = {0};
inline constexpr cat::Shader kShaders[] = {{"solid", kSolidAxes, kSolidVariants, kSolidModules}};

inline constexpr cat::Catalog kCatalog{kShaders, kModules, kContractAttributes, {}, "#version 330 core"};

// --- Helpers -----------------------------------------------------------------------
inline constexpr int kSize = 64;

// Triangle (-0.5,-0.5) (0.5,-0.5) (0,0.5) with red, green, blue corners, bound to
// the contract locations 0 (a_position) and 1 (a_color).
class TriangleMesh {
  public:
    TriangleMesh() {
        const float vertices[] = {
            -0.5f, -0.5f, 1.f, 0.f, 0.f, 1.f,  //
            0.5f,  -0.5f, 0.f, 1.f, 0.f, 1.f,  //
            0.0f,  0.5f,  0.f, 0.f, 1.f, 1.f,  //
        };
        glGenVertexArrays(1, &vao_);
        glGenBuffers(1, &vbo_);
        glBindVertexArray(vao_);
        glBindBuffer(GL_ARRAY_BUFFER, vbo_);
        glBufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices, GL_STATIC_DRAW);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                              reinterpret_cast<const void*>(2 * sizeof(float)));
        glEnableVertexAttribArray(1);
        glBindVertexArray(0);
    }
    ~TriangleMesh() {
        glDeleteBuffers(1, &vbo_);
        glDeleteVertexArrays(1, &vao_);
    }
    TriangleMesh(const TriangleMesh&) = delete;
    TriangleMesh& operator=(const TriangleMesh&) = delete;

    void draw() const {
        glBindVertexArray(vao_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
    }

  private:
    GLuint vao_ = 0, vbo_ = 0;
};

// Clears `fb` to opaque black and draws the triangle with `program`.
inline void drawTriangle(const gl::Framebuffer& fb, const gl::Program& program) {
    fb.clear({0.f, 0.f, 0.f, 1.f});
    TriangleMesh mesh;
    program.use();
    mesh.draw();
    gl::throwIfGlError("drawing the test triangle");
}

}  // namespace prism::test
