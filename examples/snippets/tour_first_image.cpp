// docs/runtime.md, "Uniforms, a framebuffer and a PNG": everything of the tour so far in one
// program that draws a lit sphere into an off-screen framebuffer and writes it to a PNG.
// Compiled and run by tests/snippets (snippets.tour_first_image).
// [snippet]
#include <glm/ext/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <iostream>

#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"  // the GL 4.5 core loader header, for glEnable
#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/shaders.hpp"

int main() {
    auto context = prism::gl::createContext();

    prism::view::Lights lights;
    lights.ambient = {0.08f, 0.08f, 0.1f};
    lights.directional.push_back({.direction = {-0.4f, -0.6f, -0.7f}, .color = {1.0f, 0.95f, 0.85f}});
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    const auto values = prism::render::variantFor(phong, prism::render::featuresOf(lights, false));
    const prism::catalog::Variant* variant = prism::catalog::findVariant(phong, values);
    if (variant == nullptr) return 1;  // those values exist, but the build did not generate them
    prism::gl::Program program(*variant, prism::shaders::kCatalog.contractAttributes, "phong");

    prism::geometry::Mesh sphere = prism::geometry::makeIcosphere(1.0f, 3);  // with unit normals
    prism::render::GpuMesh mesh(sphere, prism::shaders::kCatalog.contractAttributes);

    // An RGBA8 colour texture plus a depth buffer; bind() also sets the viewport.
    prism::gl::Framebuffer target(256, 256);
    target.bind();
    target.clear({0.05f, 0.06f, 0.08f, 1.0f});
    glEnable(GL_DEPTH_TEST);

    // The contract's uniforms (modules/contract.json): u_world, u_view, u_projection,
    // u_normal, the lights and the material, set from plain C++ values ...
    prism::view::Camera camera{.eye = {0.0f, 1.2f, 3.0f}, .target = {0.0f, 0.0f, 0.0f}};
    prism::view::Material material{.color = {0.9f, 0.45f, 0.2f, 1.0f}, .shininess = 32.0f, .specular = 0.5f};
    glm::mat4 world = glm::rotate(glm::mat4(1.0f), 0.6f, glm::vec3(1.0f, 0.0f, 0.0f));
    program.use();
    prism::render::setFrameUniforms(program, camera, /*aspect*/ 1.0f, lights, world, material);
    // ... and any uniform by name; set() checks the name and the GLSL type.
    program.set("u_color", glm::vec4(0.2f, 0.5f, 0.9f, 1.0f));
    mesh.draw(program);  // a program attribute the mesh does not feed throws, naming it

    // Read back (row 0 is the top row) and write atomically (a temp file, then rename).
    prism::image::Image8 image = target.readImage8();
    prism::image::writePng("out/sphere.png", image);
    std::cout << "wrote out/sphere.png, " << image.width << "x" << image.height << "\n";
    return image.at(128, 128) != image.at(0, 0) ? 0 : 1;  // the sphere covers the centre
}
// [/snippet]
