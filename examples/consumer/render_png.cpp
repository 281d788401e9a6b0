// Example consumer of Prism's installed runtime: renders the consumer's own tinted Phong
// shader (Prism's lighting modules plus its tint.glsl, from its lit_shaders catalogue) on
// an icosphere, headlessly, to a PNG; with --golden it also compares against a golden
// image (at most 3/255 per channel on at most 0.1% of pixels, mean error at most 0.5).
//
//     prism_consumer_render out.png [--golden golden.png]
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>

#include "consumer/lit_shaders.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/image/image_compare.hpp"
#include "prism/image/png_io.hpp"
#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/render/gpu_mesh.hpp"

int main(int argc, char** argv) {
    if (argc != 2 && !(argc == 4 && std::strcmp(argv[2], "--golden") == 0)) {
        std::cerr << "usage: prism_consumer_render OUT.png [--golden GOLDEN.png]\n";
        return 2;
    }
    try {
        auto context = prism::gl::createContext();  // EGL surfaceless, else OSMesa: no display needed

        // One warm key light and no fog: the variant with one directional light, no point lights.
        prism::view::Lights lights;
        lights.ambient = glm::vec3(0.1f);
        lights.directional.push_back({glm::vec3(-0.4f, -0.5f, -0.75f), glm::vec3(1.0f, 0.95f, 0.85f)});
        const auto& shader = consumer::lit::shaderInfo(consumer::lit::ShaderId::tinted_phong);
        const auto values =
            prism::render::variantFor(shader, prism::render::featuresOf(lights, false), {{"BLINN", "1"}});
        const prism::catalog::Variant* variant = prism::catalog::findVariant(shader, values);
        if (variant == nullptr) throw std::runtime_error("tinted_phong: that variant was not generated");
        prism::gl::Program program(*variant, consumer::lit::kCatalog.contractAttributes, "tinted_phong");

        prism::geometry::Mesh sphere = prism::geometry::makeIcosphere(1.0f, 4);
        prism::render::GpuMesh mesh(sphere, consumer::lit::kCatalog.contractAttributes);

        prism::gl::Framebuffer target(128, 128);
        target.clear({0.05f, 0.05f, 0.08f, 1.0f});
        glEnable(GL_DEPTH_TEST);
        prism::view::Camera camera;
        camera.eye = {0.0f, 0.4f, 3.0f};
        const prism::view::Material material{.color = {0.8f, 0.8f, 0.8f, 1.0f}, .shininess = 48.0f, .specular = 0.6f};
        program.use();
        prism::render::setFrameUniforms(program, camera, 1.0f, lights, glm::mat4(1.0f), material);
        program.set("u_tint", glm::vec4(0.3f, 0.7f, 1.0f, 0.5f));  // the consumer's own uniform
        mesh.draw(program);

        const prism::image::Image8 image = target.readImage8();
        prism::image::writePng(argv[1], image);
        std::cout << "prism_consumer_render: wrote " << argv[1] << " (" << context->info().renderer << ")\n";
        if (argc == 4) {
            const auto stats = prism::image::compareImages(image, prism::image::readPng(argv[3]));
            const prism::image::Thresholds thresholds{.maxChannelDiff = 3, .maxShareOver = 0.001, .maxMean = 0.5};
            std::cout << "golden " << argv[3] << ": " << prism::image::describe(stats, thresholds) << "\n";
            if (!prism::image::passes(stats, thresholds)) return 1;
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "prism_consumer_render: error: " << e.what() << "\n";
        return 1;
    }
}
