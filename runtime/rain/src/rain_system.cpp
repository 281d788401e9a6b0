// The GPU rain (see prism/rain/rain_system.hpp).
#include "prism/rain/rain_system.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "prism/gl/draw_state.hpp"
#include "prism/gl/gl.hpp"
#include "prism/rain/streak_texture.hpp"
#include "prism/rain_shaders.hpp"
#include "texture_arrays.hpp"

namespace prism::rain {
namespace {

constexpr int kStreakTextureUnit = 0;
constexpr std::uint32_t kComputeGroupSize = 256;  // local_size_x of rain_init.comp and rain_update.comp
constexpr std::uint32_t kCullBlock = 64 * 16;     // rain_cull.comp: local_size_x x RAIN_CULL_RUN particles
// One DrawArraysIndirectCommand (count, instanceCount, first, baseInstance) per block and technique kind.
constexpr std::size_t kDrawCommandBytes = 4 * sizeof(std::uint32_t);
// The particles are written by compute and read as vertices, copied or read back.
constexpr GLbitfield kParticleBarriers =
    GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT;

render::VariantValues fogVariant(const view::Fog* fog) {
    return {{"FOG", fog ? "1" : "0"}};
}

}  // namespace

std::string_view techniqueShader(StreakTechnique t) {
    switch (t) {
        case StreakTechnique::GeometryShader: return "rain_streaks";
        case StreakTechnique::Instanced: return "rain_instanced";
        case StreakTechnique::PointSprites: return "rain_points";
    }
    return "rain_streaks";
}

RainSystem::RainSystem(RainPrograms& programs, const RainParams& params, const glm::vec3& eye)
    : programs_(programs), weather_(params) {
    gl::requireCompute("rain: the GPU particle update");
    validateEye(eye);
    fastestFall_ = weather_.rate.fallSpeed;
    center_ = cylinderCenter(weather_.params, eye);
    shearHeight_ = shearHeight(weather_.params, eye);
    resize(particleCountFor(weather_.params));
}

std::size_t RainSystem::gpuBytes() const {
    return particleBytes() + streakTextureBytes_;
}

std::size_t RainSystem::particleBytes() const {
    return particles_.bytes() + visible_.bytes() + drawCommands_.bytes();
}

void RainSystem::resize(std::uint32_t count) {
    if (count > capacity_) {
        // Grow by at least a quarter so a slowly rising intensity does not reallocate
        // every frame; the old particles are copied, the new ones seeded.
        std::uint64_t wanted = capacity_ == 0 ? count : std::max<std::uint64_t>(count, capacity_ + capacity_ / 4);
        wanted = std::min<std::uint64_t>(wanted, kMaxParticles);
        gl::Buffer bigger = gl::Buffer::create(static_cast<std::size_t>(wanted) * sizeof(Particle), GL_DYNAMIC_DRAW);
        if (particles_ && count_ > 0) {
            glMemoryBarrier(kParticleBarriers);
            glBindBuffer(GL_COPY_READ_BUFFER, particles_.id());
            glBindBuffer(GL_COPY_WRITE_BUFFER, bigger.id());
            glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0,
                                static_cast<GLsizeiptr>(count_) * static_cast<GLsizeiptr>(sizeof(Particle)));
            glBindBuffer(GL_COPY_READ_BUFFER, 0);
            glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
        }
        particles_ = std::move(bigger);
        capacity_ = static_cast<std::uint32_t>(wanted);
        pointsVao_.reset();
        instancedVao_.reset();
        visible_.reset();
        drawCommands_.reset();
    }
    if (count > count_) seedRange(count_, count);
    count_ = count;
    gl::throwIfGlError("rain: resizing the particle buffer");
}

void RainSystem::seedRange(std::uint32_t first, std::uint32_t end) {
    if (end <= first) return;
    gl::Program& init = programs_.get("rain_init");
    init.use();
    init.set(rain_shaders::rain_init::u_cylinderCenter, center_);
    init.set(rain_shaders::rain_init::u_cylinder, glm::vec2(weather_.params.radius, weather_.params.height));
    init.set(rain_shaders::rain_init::u_lod,
             glm::vec2(static_cast<float>(weather_.params.lodRings), weather_.params.lodFalloff));
    init.set(rain_shaders::rain_init::u_wind, weather_.wind);
    init.set(rain_shaders::rain_init::u_fallSpeed, weather_.rate.fallSpeed);
    init.set(rain_shaders::rain_init::u_jitter, weather_.params.jitter);
    init.set(rain_shaders::rain_init::u_rainSeed, weather_.params.seed);
    init.set(rain_shaders::rain_init::u_firstParticle, first);
    init.set(rain_shaders::rain_init::u_particleCount, end);
    init.set(rain_shaders::rain_init::u_shearHeight, shearHeight_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, particles_.id());
    gl::dispatchInvocations(end - first, kComputeGroupSize);
    glMemoryBarrier(kParticleBarriers);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
}

void RainSystem::update(float dt, const glm::vec3& eye) {
    validateEye(eye);
    const float step = clampStep(dt);
    center_ = cylinderCenter(weather_.params, eye);
    shearHeight_ = shearHeight(weather_.params, eye);
    ++steps_;
    if (count_ == 0) return;
    const gl::ScopedDrawState keep;
    gl::Program& update = programs_.get("rain_update");
    update.use();
    update.set(rain_shaders::rain_update::u_cylinderCenter, center_);
    update.set(rain_shaders::rain_update::u_cylinder, glm::vec2(weather_.params.radius, weather_.params.height));
    update.set(rain_shaders::rain_update::u_dt, step);
    update.set(rain_shaders::rain_update::u_wind, weather_.wind);
    update.set(rain_shaders::rain_update::u_fallSpeed, weather_.rate.fallSpeed);
    update.set(rain_shaders::rain_update::u_particleCount, count_);
    update.set(rain_shaders::rain_update::u_shearHeight, shearHeight_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, particles_.id());
    gl::dispatchInvocations(count_, kComputeGroupSize);
    glMemoryBarrier(kParticleBarriers);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
}

void RainSystem::setIntensity(float intensity) {
    weather_.setIntensity(intensity);
    fastestFall_ = std::max(fastestFall_, weather_.rate.fallSpeed);  // drops keep their speed until they respawn
    resize(particleCountFor(weather_.params));
}

void RainSystem::setWind(const WindParams& wind) {
    weather_.setWind(wind);
}

void RainSystem::ensureStreakTexture() {
    if (streakTexture_) return;
    const StreakTextureArray t = generateStreakTextures();
    const std::vector<std::uint8_t> packed = packStreakBinCorners(t);
    streakTexture_ = uploadTextureArray8(t.width, t.height, t.layers, 4, packed.data(), false);
    streakTextureBytes_ = packed.size();
}

void RainSystem::bindAttributes(const gl::VertexArray& vao, const gl::Buffer& source, unsigned divisor) {
    const auto& c = programs_.catalog();
    glBindVertexArray(vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, source.id());
    const std::pair<const char*, std::size_t> attributes[] = {
        {"a_rainSeed", offsetof(Particle, seed)},
        {"a_rainPosition", offsetof(Particle, position)},
        {"a_rainVelocity", offsetof(Particle, velocity)},
    };
    for (const auto& [name, offset] : attributes) {
        const auto location = static_cast<GLuint>(catalog::attributeLocation(c, name));
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, 4, GL_FLOAT, GL_FALSE, sizeof(Particle), reinterpret_cast<const void*>(offset));
        glVertexAttribDivisor(location, divisor);
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

std::uint32_t RainSystem::cullBlocks() const {
    return (count_ + kCullBlock - 1) / kCullBlock;
}

void RainSystem::setStreakUniforms(gl::Program& p, const RainDrawInputs& in) const {
    const StreakStyle& s = weather_.params.streaks;
    p.set(rain_shaders::contract::u_view, in.camera.view());
    p.set(rain_shaders::contract::u_projection, in.camera.projection(in.aspect));
    p.set(rain_shaders::contract::u_cameraPosition, in.camera.eye);
    p.set(rain_shaders::contract::u_cylinderCenter, center_);
    p.set(rain_shaders::contract::u_cylinder, glm::vec2(weather_.params.radius, weather_.params.height));
    p.set(rain_shaders::contract::u_wind, weather_.wind);
    p.set(rain_shaders::contract::u_exposure, s.exposure);
    p.set(rain_shaders::contract::u_streakWidth, glm::vec2(s.width, s.widthPerMetre));
    p.set(rain_shaders::contract::u_viewportHeight, static_cast<float>(std::max(in.viewportHeight, 1)));
    p.set(rain_shaders::contract::u_streakOpacity, s.opacity);
    p.set(rain_shaders::contract::u_streakFalloff, s.falloffDistance);
    p.set(rain_shaders::contract::u_lod,
          glm::vec2(static_cast<float>(weather_.params.lodRings), weather_.params.lodFalloff));
}

void RainSystem::cullToView(const RainDrawInputs& in) {
    if (!visible_) {
        const std::uint64_t blocks = (std::uint64_t{capacity_} + kCullBlock - 1) / kCullBlock;
        visible_ =
            gl::Buffer::create(static_cast<std::size_t>(blocks * kCullBlock) * sizeof(Particle), GL_DYNAMIC_DRAW);
        drawCommands_ = gl::Buffer::create(static_cast<std::size_t>(2 * blocks) * kDrawCommandBytes, GL_DYNAMIC_DRAW);
        pointsVao_.reset();
        instancedVao_.reset();
    }
    gl::Program& cull = programs_.get("rain_cull");
    cull.use();
    setStreakUniforms(cull, in);
    cull.set(rain_shaders::rain_cull::u_particleCount, count_);
    // The longest streak: a drop's speed is at most 1.1 x the fall speed it respawned with, plus its
    // sideways jitter (up to `jitter` on each horizontal axis), plus the wind; 1 % margin for rounding.
    const float fastest = 1.1f * fastestFall_ + std::sqrt(2.0f) * weather_.params.jitter + glm::length(weather_.wind);
    cull.set(rain_shaders::rain_cull::u_maxStreakLength, 1.01f * fastest * weather_.params.streaks.exposure);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, particles_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, visible_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, drawCommands_.id());
    gl::dispatchGroups(cullBlocks());
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | kParticleBarriers);
    for (GLuint binding = 0; binding < 3; ++binding) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
}

void RainSystem::draw(const RainDrawInputs& in) {
    if (count_ == 0) return;
    const gl::ScopedDrawState keep;  // the caller's blend, depth, bindings and unit, put back on return
    ensureStreakTexture();
    if (in.cullToView) cullToView(in);
    const bool culled = in.cullToView;
    const bool instanced = in.technique == StreakTechnique::Instanced;
    gl::VertexArray& vao = instanced ? instancedVao_ : pointsVao_;
    if (!vao || vaoReadsVisible_[instanced] != culled) {
        vao = gl::VertexArray::create();
        bindAttributes(vao, culled ? visible_ : particles_, instanced ? 1u : 0u);
        vaoReadsVisible_[instanced] = culled;
    }
    gl::Program& p = programs_.get(techniqueShader(in.technique), fogVariant(in.fog));
    p.use();
    setStreakUniforms(p, in);
    p.set(rain_shaders::contract::u_streakTexture, kStreakTextureUnit);
    p.set(rain_shaders::contract::u_ambient, in.lights.ambient);
    p.set(rain_shaders::contract::u_sunDirection, glm::normalize(in.lights.sun.direction));
    p.set(rain_shaders::contract::u_sunColor, in.lights.sun.color);
    p.set(rain_shaders::contract::u_lampPosition, in.lights.lamp.position);
    p.set(rain_shaders::contract::u_lampColor, in.lights.lamp.color);
    p.set(rain_shaders::contract::u_lampRange, in.lights.lampRange);
    if (in.fog) {
        p.set(rain_shaders::contract::u_fogColor, in.fog->color);
        p.set(rain_shaders::contract::u_fogDensity, in.fog->density);
    }
    glActiveTexture(GL_TEXTURE0 + kStreakTextureUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, streakTexture_.id());

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBlendEquation(GL_FUNC_ADD);  // premultiplied "over": nothing else may be left here
    if (in.technique == StreakTechnique::PointSprites) glEnable(GL_PROGRAM_POINT_SIZE);
    p.reportUnsetUniforms();
    glBindVertexArray(vao.id());
    if (culled)
        drawVisible(in.technique);
    else
        drawAll(in.technique);
    gl::throwIfGlError("rain: drawing " + std::string(techniqueName(in.technique)));
}

void RainSystem::drawAll(StreakTechnique technique) const {
    if (technique == StreakTechnique::Instanced)
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count_));
    else
        glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
}

void RainSystem::drawVisible(StreakTechnique technique) const {
    const std::uint32_t blocks = cullBlocks();
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, drawCommands_.id());
    if (technique == StreakTechnique::Instanced)
        glMultiDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(blocks * kDrawCommandBytes),
                                  static_cast<GLsizei>(blocks), 0);
    else
        glMultiDrawArraysIndirect(GL_POINTS, nullptr, static_cast<GLsizei>(blocks), 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

std::uint32_t RainSystem::visibleCount() const {
    if (!drawCommands_ || count_ == 0) return count_;
    std::vector<std::uint32_t> commands(4 * static_cast<std::size_t>(cullBlocks()));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_COPY_READ_BUFFER, drawCommands_.id());
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(commands.size() * sizeof(std::uint32_t)),
                       commands.data());
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    std::uint32_t visible = 0;
    for (std::size_t b = 0; b < commands.size(); b += 4) visible += commands[b];
    return visible;
}

std::vector<Particle> RainSystem::readParticles() const {
    std::vector<Particle> out(count_);
    if (count_ == 0) return out;
    glMemoryBarrier(kParticleBarriers);
    glBindBuffer(GL_COPY_READ_BUFFER, particles_.id());
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0,
                       static_cast<GLsizeiptr>(count_) * static_cast<GLsizeiptr>(sizeof(Particle)), out.data());
    glBindBuffer(GL_COPY_READ_BUFFER, 0);
    gl::throwIfGlError("rain: reading the particles back");
    return out;
}

}  // namespace prism::rain
