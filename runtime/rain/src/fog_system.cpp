// GL drawing of the fog billboards (see prism/rain/fog_system.hpp).
#include "prism/rain/fog_system.hpp"

#include <cmath>

#include "prism/gl/draw_state.hpp"
#include "prism/gl/gl.hpp"
#include "prism/rain/rain_params.hpp"
#include "prism/rain_shaders.hpp"
#include "texture_arrays.hpp"

namespace prism::rain {
namespace {

constexpr int kNoiseTextureUnit = 1;

}  // namespace

FogSystem::FogSystem(RainPrograms& programs, const SceneFog& fog, const glm::vec3& eye)
    : programs_(programs),
      params_(fog.billboards),
      simulation_(fog.billboards, eye),
      noise_(generateFogNoise(64, 16, fog.billboards.seed)),
      buffer_(gl::Buffer::create(static_cast<std::size_t>(fog.billboards.count) * sizeof(glm::vec4), GL_DYNAMIC_DRAW,
                                 simulation_.billboards().data())),
      vao_(gl::VertexArray::create()),
      noiseTexture_(uploadTextureArray8(noise_.size, noise_.size, noise_.layers, 1, noise_.texels.data(), true)) {
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    const auto location = static_cast<GLuint>(catalog::attributeLocation(programs_.catalog(), "a_fogBillboard"));
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), nullptr);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    gl::throwIfGlError("rain: creating the fog billboards");
}

void FogSystem::update(float dt, const glm::vec3& eye, const glm::vec3& wind) {
    simulation_.step(dt, eye, wind);
    const auto& b = simulation_.billboards();
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(b.size() * sizeof(glm::vec4)), b.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void FogSystem::setStrength(float strength) {
    if (!(strength >= 0.0f && strength <= 1.0f))
        throw RainParameterError("rain: fog billboard strength must be in [0, 1] (got " + std::to_string(strength) +
                                 ")");
    params_.strength = strength;
}

void FogSystem::draw(const view::Camera& camera, float aspect, const view::Fog* distanceFog, float timeSeconds) {
    if (params_.strength <= 0.0f) return;
    const gl::ScopedDrawState keep;  // the caller's blend, depth, bindings and unit, put back on return
    gl::Program& p = programs_.get("fog_billboards", {{"FOG", distanceFog ? "1" : "0"}});
    p.use();
    p.set(rain_shaders::fog_billboards::u_view, camera.view());
    p.set(rain_shaders::fog_billboards::u_projection, camera.projection(aspect));
    p.set(rain_shaders::fog_billboards::u_cameraPosition, camera.eye);
    p.set(rain_shaders::fog_billboards::u_fogBillboardSize, params_.size);
    p.set(rain_shaders::fog_billboards::u_fogStrength, params_.strength);
    p.set(rain_shaders::fog_billboards::u_fogBillboardColor, params_.color);
    p.set(rain_shaders::fog_billboards::u_fogGroundHeight, params_.groundHeight);
    p.set(rain_shaders::fog_billboards::u_fogSoftDistance, params_.softDistance);
    p.set(rain_shaders::fog_billboards::u_time, timeSeconds);
    p.set(rain_shaders::fog_billboards::u_fogNoise, kNoiseTextureUnit);
    if (distanceFog) {
        p.set(rain_shaders::fog_billboards::u_fogColor, distanceFog->color);
        p.set(rain_shaders::fog_billboards::u_fogDensity, distanceFog->density);
    }
    glActiveTexture(GL_TEXTURE0 + kNoiseTextureUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, noiseTexture_.id());
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquation(GL_FUNC_ADD);  // premultiplied "over": nothing else may be left here
    p.reportUnsetUniforms();
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(simulation_.billboards().size()));
    gl::throwIfGlError("rain: drawing the fog billboards");
}

}  // namespace prism::rain
