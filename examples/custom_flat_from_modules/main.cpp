// custom_flat_from_modules: the "flat shader from modules" example of the FUDGE shader
// thesis (§7.1 and its appendix "Custom Shader Beispiel"), done with Prism's composition
// API. The thesis concatenated SHADER_MODULE strings
// (HEAD_VERT + LIGHTS + NORMAL_FACE + ... + FLAT_MAIN_VERT); here the modules are
// named by ModuleId, their dependencies (math_utils, transforms) come in once and in
// order, one #version is emitted, and a GLSL error would point at the module's own
// file and line. Renders a flat-shaded icosphere to custom_flat.png and checks that
// something was drawn.
//   custom_flat_from_modules [output.png]      (any other argument: usage error, exit 2)
#include <glm/gtc/matrix_transform.hpp>

#include <iostream>

#include "prism/gl/compose.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/geometry/normals.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/image/png_io.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/shaders.hpp"

using prism::shaders::ModuleId;

namespace {

constexpr const char* kVertexMain = R"glsl(in vec3 a_position;
in vec3 a_normal;
flat out vec4 v_color;

void main() {
    vec4 eye = eyePosition(a_position);
    vec3 n = eyeNormal(a_normal);
    vec3 c = u_ambient;
    for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i) {
        if (i >= u_directionalLightCount) break;
        c += max(dot(n, directionToLight(i)), 0.0) * u_lightColor[i];
    }
    v_color = vec4(c, 1.0);
    gl_Position = clipPosition(eye);
}
)glsl";

constexpr const char* kFragmentMain = R"glsl(flat in vec4 v_color;

void main() {
    frag = u_color * v_color;
}
)glsl";

std::uint32_t id(ModuleId m) {
    return static_cast<std::uint32_t>(m);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {  // nothing is silently ignored
        const bool help = argc == 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
        (help ? std::cout : std::cerr) << "usage: custom_flat_from_modules [output.png]\n";
        return help ? 0 : 2;
    }
    const std::string out = argc > 1 ? argv[1] : "custom_flat.png";
    try {
        auto context = prism::gl::createContext();
        std::vector<prism::gl::ComposeStage> stages{
            {prism::catalog::Stage::Vertex,
             {id(ModuleId::lights), id(ModuleId::normals)},
             kVertexMain,
             "examples/custom_flat_from_modules/flat_main.vert"},
            {prism::catalog::Stage::Fragment,
             {id(ModuleId::material), id(ModuleId::fragment_output)},
             kFragmentMain,
             "examples/custom_flat_from_modules/flat_main.frag"},
        };
        for (const auto& s : stages) {
            std::cout << prism::catalog::stageName(s.stage) << " modules:";
            for (auto m : prism::gl::moduleOrder(prism::shaders::kCatalog, s.modules))
                std::cout << " " << prism::shaders::name(static_cast<ModuleId>(m));
            std::cout << "\n";
        }
        auto program = prism::gl::composeProgram(prism::shaders::kCatalog, stages, "custom flat");

        // Face normals on vertices split per face: the thesis's NORMAL_FACE module.
        auto mesh = prism::geometry::makeFlatShaded(prism::geometry::makeIcosphere(1.0f, 2));
        prism::render::GpuMesh gpu(mesh, prism::shaders::kCatalog.contractAttributes);
        prism::gl::Framebuffer fb(256, 256);
        fb.bind();
        fb.clear({0.0f, 0.0f, 0.0f, 1.0f});
        glEnable(GL_DEPTH_TEST);
        prism::view::Material material{{0.3f, 0.6f, 0.9f, 1.0f}, 1.0f, 0.0f};
        program.use();
        prism::render::setFrameUniforms(program, prism::render::defaultCamera(), 1.0f, prism::render::defaultLights(),
                                        glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0, 1, 0)), material);
        gpu.draw();
        auto image = fb.readImage8();
        prism::image::writePng(out, image);

        std::size_t lit = 0;
        for (std::size_t i = 0; i < image.pixelCount(); ++i) lit += image.data[i * 4 + 2] > 0;
        std::cout << "wrote " << out << ": " << lit << " of " << image.pixelCount() << " pixels drawn\n";
        return lit > image.pixelCount() / 10 ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "custom_flat_from_modules: error: " << e.what() << "\n";
        return 1;
    }
}
