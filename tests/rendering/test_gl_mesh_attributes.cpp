// Issue 22, item 4 (safe defaults): an attribute that a program reads and the mesh does
// not feed is an error naming the program's own attribute, with "did you mean" (before,
// a misspelled a_positon read zeros, or the contract lookup named 'a_position' instead).
#include <gtest/gtest.h>

#include <string>

#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/program.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"
#include "rendering_test_support.hpp"

namespace {

using namespace prism;
class MeshAttributes : public prism::test::GlTest {};

// A program from raw sources, its attributes bound at the contract's locations as the
// runtime binds a catalogue variant's.
gl::Program programReading(const std::string& positionName) {
    gl::ProgramSources sources;
    sources.label = "toon";
    sources.stages.push_back({catalog::Stage::Vertex,
                              "#version 330 core\nin vec3 " + positionName +
                                  ";\nin vec3 a_normal;\nout vec3 v_n;\n"
                                  "void main() { v_n = a_normal; gl_Position = vec4(" +
                                  positionName + ", 1.0); }\n",
                              {}});
    sources.stages.push_back(
        {catalog::Stage::Fragment,
         "#version 330 core\nin vec3 v_n;\nout vec4 frag;\nvoid main() { frag = vec4(v_n, 1.0); }\n",
         {}});
    for (const auto& a : shaders::kCatalog.contractAttributes)
        sources.attributes.push_back({std::string(a.name), a.location});
    return gl::Program(std::move(sources));
}

}  // namespace

TEST_F(MeshAttributes, MisspelledAttributeIsNamedWithDidYouMean) {
    const render::GpuMesh mesh(geometry::makeCube(), shaders::kCatalog.contractAttributes);
    const gl::Program program = programReading("a_positon");
    try {
        mesh.requireAttributesOf(program);
        FAIL() << "a program reading a_positon must not draw from a mesh that feeds a_position";
    } catch (const render::MeshAttributeError& e) {
        EXPECT_STREQ(e.what(),
                     "program 'toon' reads vertex attribute 'a_positon', which the mesh does not provide "
                     "(did you mean 'a_position'?); the mesh provides a_position, a_normal: fix the name "
                     "in the shader, or feed it with a vertex array of your own");
    }
    program.use();
    EXPECT_THROW(mesh.draw(program), render::MeshAttributeError);
}

TEST_F(MeshAttributes, ProgramReadingWhatTheMeshFeedsDraws) {
    const render::GpuMesh mesh(geometry::makeCube(), shaders::kCatalog.contractAttributes);
    const gl::Program program = programReading("a_position");
    ASSERT_EQ(program.activeAttributes().size(), 2u);
    gl::Framebuffer target(16, 16);  // surfaceless EGL has no default framebuffer to draw into
    target.bind();
    program.use();
    EXPECT_NO_THROW(mesh.draw(program));
    // Every catalogue shader reads only what a mesh feeds (what renderImage8 relies on).
    for (const auto& shader : shaders::kCatalog.shaders)
        EXPECT_NO_THROW(mesh.requireAttributesOf(rendering_test::programCache().get(std::string(shader.name))))
            << shader.name;
}
