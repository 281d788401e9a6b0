// GPU frames of the soft-shadow demo: R32UI sampler tables, one full-screen draw per
// frame into an RGBA32F framebuffer, read back for the CPU frame loop.
#include "prism/bluenoise/gl_soft_shadows.hpp"

#include <chrono>
#include <stdexcept>

#include <glm/glm.hpp>

#include "prism/bluenoise_shaders.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/draw_state.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/render/program_cache.hpp"

namespace prism::bluenoise {

namespace detail {

// A 2D R32UI texture (nearest filtering), owned through a prism::gl handle. Named, not in
// the anonymous namespace: GlSoftShadows::Resources, which the header declares, holds three.
class UintTexture {
  public:
    UintTexture() : texture_(gl::Texture::create()) {}

    void upload(int unit, int width, int height, const std::vector<std::uint32_t>& values) {
        if (values.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
            throw std::invalid_argument("prism::bluenoise: table size does not match its values");
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, width, height, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, values.data());
    }

  private:
    gl::Texture texture_;
};

}  // namespace detail

namespace {

namespace soft_shadows = bluenoise_shaders::soft_shadows;  // the shader's typed uniforms

// The full-screen triangle writes every pixel as the shader computes it, whatever state the
// caller left: an enabled depth test against the never-cleared depth buffer, blending or
// culling would keep or mix in stale pixels (docs/gpu.md, "Vulkan": seen on NVIDIA and on
// llvmpipe after other draws in the same context). ScopedDrawState puts the caller's back.
void disableFixedFunctionTests() {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace

struct GlSoftShadows::Resources {
    Resources(int w, int h) : framebuffer(w, h, gl::ColorFormat::Rgba32F), programs(bluenoise_shaders::kCatalog) {}
    gl::Framebuffer framebuffer;
    render::ProgramCache programs;
    detail::UintTexture mask, seeds, stack;
    gl::VertexArray vao = gl::VertexArray::create();
};

GlSoftShadows::GlSoftShadows(int width, int height) : gl_(std::make_unique<Resources>(width, height)) {}
GlSoftShadows::~GlSoftShadows() = default;

RealImage GlSoftShadows::render(const SoftShadowScene& scene, StochasticSetup& setup, const RenderOptions& options) {
    const SoftShadowUniforms u = softShadowUniforms(scene, setup.tables, options);  // throws for > 3 spheres
    const gl::ScopedDrawState keep;  // the caller's framebuffer, viewport, bindings and unit, put back on return
    if (options.width != gl_->framebuffer.width() || options.height != gl_->framebuffer.height())
        throw std::invalid_argument("prism::bluenoise::GlSoftShadows: options size differs from the framebuffer's");
    gl::Program& program = gl_->programs.get("soft_shadows");
    program.use();
    program.set(soft_shadows::u_blueNoiseMask, 0);
    program.set(soft_shadows::u_blueNoiseSeeds, 1);
    program.set(soft_shadows::u_blueNoiseStack, 2);
    program.set(soft_shadows::u_blueNoiseStackDepth, u.stackDepth);
    program.set(soft_shadows::u_blueNoiseSampler, u.sampler);
    program.set(soft_shadows::u_spp, u.spp);
    program.set(soft_shadows::u_imageSize, glm::vec2(u.imageSize[0], u.imageSize[1]));
    program.set(soft_shadows::u_extent, u.extent);
    program.set(soft_shadows::u_light, glm::vec4(u.light[0], u.light[1], u.light[2], u.light[3]));
    const decltype(soft_shadows::u_sphere0)* spheres[] = {&soft_shadows::u_sphere0, &soft_shadows::u_sphere1,
                                                          &soft_shadows::u_sphere2};
    for (std::size_t i = 0; i < kGpuSpheres; ++i) {
        const auto& sp = u.spheres[i];
        program.set(*spheres[i], glm::vec4(sp[0], sp[1], sp[2], sp[3]));
    }
    gl_->mask.upload(0, setup.tables.maskWidth, setup.tables.maskHeight, setup.tables.mask);
    gl_->stack.upload(2, setup.tables.stackWidth, setup.tables.stackHeight * setup.tables.stackDepth,
                      setup.tables.stack);
    return runSoftShadowPipeline(setup, options, [&](const SamplerTables& tables, std::uint32_t frame) {
        const auto start = std::chrono::steady_clock::now();
        gl_->seeds.upload(1, tables.seedWidth, tables.seedHeight, tables.seeds);
        program.use();
        program.set(soft_shadows::u_frame, static_cast<unsigned>(frame));
        program.reportUnsetUniforms();
        gl_->framebuffer.bind();
        disableFixedFunctionTests();
        glBindVertexArray(gl_->vao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const image::ImageF pixels = gl_->framebuffer.readImageF();
        gl::throwIfGlError("drawing the soft-shadow demo");
        std::vector<double> values(static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height));
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = pixels.data[i * 4];
        lastMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return values;
    });
}

}  // namespace prism::bluenoise
