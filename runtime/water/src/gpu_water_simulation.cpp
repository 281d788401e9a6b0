// The GPU water step (see gpu_water_simulation.hpp): one compute dispatch per pass with
// a shader-storage barrier between passes, the two water buffers ping-ponged.
#include "prism/water/gpu_water_simulation.hpp"

#include <array>
#include <string>
#include <utility>

#include <glm/vec2.hpp>

#include "prism/gl/compute.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/handles.hpp"
#include "prism/gl/program.hpp"
#include "prism/water_shaders.hpp"

namespace prism::water {
namespace {

namespace ws = prism::water_shaders;

// Binding points of modules/water/water_grid.glsl.
enum Binding : GLuint {
    kTerrain = 0,
    kPermeability = 1,
    kWaterIn = 2,
    kWaterOut = 3,
    kVelocity = 4,
    kFlow = 5,
    kLedgerCells = 6,
    kLedgerPartials = 7,
    kLedgerTotals = 8,
};

enum Pass {
    kRain,
    kFlowOut,
    kFlowGather,
    kDistributeVelocity,
    kDistributeApply,
    kSmooth,
    kLedgerPartial,
    kLedgerTotal,
    kPassCount
};

constexpr ws::ShaderId kPassShaders[kPassCount] = {
    ws::ShaderId::water_rain_infiltrate,     ws::ShaderId::water_flow_out,         ws::ShaderId::water_flow_gather,
    ws::ShaderId::water_distribute_velocity, ws::ShaderId::water_distribute_apply, ws::ShaderId::water_smooth,
    ws::ShaderId::water_ledger_partial,      ws::ShaderId::water_ledger_total,
};

// A storage buffer owned by `owner` (prism::gl handles); returns its name.
GLuint makeBuffer(std::vector<gl::Buffer>& owner, std::size_t bytes, const void* data) {
    return owner.emplace_back(gl::Buffer::create(bytes, GL_DYNAMIC_COPY, data)).id();
}

void fillBuffer(GLuint buffer, GLsizeiptr bytes, const void* data) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, bytes, data);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

}  // namespace

struct GpuWaterSimulation::Impl {
    std::vector<gl::Program> programs;
    std::vector<gl::Buffer> ownedBuffers;  // owns every buffer below, which are its names
    GLuint terrain = 0, permeability = 0, water[2] = {0, 0}, velocity = 0, flow = 0, ledgerCells = 0, partials = 0,
           totals = 0;
    int current = 0;
    GLuint groupsX = 1, groupsY = 1, partialCount = 1;

    void dispatch(Pass pass, GLuint x, GLuint y) {
        programs[pass].use();
        gl::dispatchGroups(x, y);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    // A pass that reads the current water and writes the other buffer.
    void waterPass(Pass pass) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterIn, water[current]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterOut, water[1 - current]);
        dispatch(pass, groupsX, groupsY);
        current = 1 - current;
    }

    void readPass(Pass pass) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWaterIn, water[current]);
        dispatch(pass, groupsX, groupsY);
    }
};

bool GpuWaterSimulation::isSupported() {
    return gl::computeAvailable();
}

GpuWaterSimulation::GpuWaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params)
    : WaterSimulation(std::move(terrain), std::move(permeability), params), impl_(std::make_unique<Impl>()) {
    gl::requireCompute("prism water: the GPU simulation (or use the CPU simulation)");
    for (ws::ShaderId id : kPassShaders) {
        const auto& shader = ws::shaderInfo(id);
        impl_->programs.emplace_back(shader.variants[0], ws::kCatalog.contractAttributes, std::string(shader.name));
    }
    const std::size_t n = cellCount();
    impl_->groupsX = static_cast<GLuint>((width() + 15) / 16);
    impl_->groupsY = static_cast<GLuint>((height() + 15) / 16);
    impl_->partialCount = static_cast<GLuint>((n + 255) / 256);
    const auto bytes = [](std::size_t count, std::size_t size) { return count * size; };
    impl_->terrain = makeBuffer(impl_->ownedBuffers, bytes(n, sizeof(float)), terrain_.heights.data());
    impl_->permeability = makeBuffer(impl_->ownedBuffers, bytes(n, sizeof(float)), permeability_.data());
    for (GLuint& w : impl_->water) w = makeBuffer(impl_->ownedBuffers, bytes(n, sizeof(glm::vec2)), nullptr);
    impl_->velocity = makeBuffer(impl_->ownedBuffers, bytes(n, sizeof(glm::vec2)), nullptr);
    impl_->flow = makeBuffer(impl_->ownedBuffers, bytes(n, sizeof(glm::vec2)), nullptr);
    impl_->ledgerCells = makeBuffer(impl_->ownedBuffers, bytes(n, 2 * sizeof(double)), nullptr);
    impl_->partials = makeBuffer(impl_->ownedBuffers, bytes(impl_->partialCount, 2 * sizeof(double)), nullptr);
    impl_->totals = makeBuffer(impl_->ownedBuffers, bytes(1, 2 * sizeof(double)), nullptr);
    gl::throwIfGlError("creating the water simulation's storage buffers");
    for (auto& p : impl_->programs) {
        p.set(ws::contract::u_gridSize, glm::ivec2(width(), height()));
        p.set(ws::contract::u_partialCount, static_cast<int>(impl_->partialCount));
    }
    std::vector<glm::vec2> zero(n, glm::vec2(0.0f));
    resetState(zero);
}

GpuWaterSimulation::~GpuWaterSimulation() = default;

std::size_t GpuWaterSimulation::programCount() const {
    return impl_->programs.size();
}

unsigned GpuWaterSimulation::depthBuffer() const {
    return impl_->water[impl_->current];
}

void GpuWaterSimulation::finish() const {
    glFinish();
}

void GpuWaterSimulation::resetState(std::span<const glm::vec2> pairs) {
    const std::size_t n = cellCount();
    const auto vecBytes = static_cast<GLsizeiptr>(n * sizeof(glm::vec2));
    std::vector<glm::vec2> zero(n, glm::vec2(0.0f));
    std::vector<glm::vec2> flowZero(n, glm::vec2(0.0f, 4.0f));
    impl_->current = 0;
    fillBuffer(impl_->water[0], vecBytes, pairs.data());
    fillBuffer(impl_->water[1], vecBytes, zero.data());
    fillBuffer(impl_->velocity, vecBytes, zero.data());
    fillBuffer(impl_->flow, vecBytes, flowZero.data());
    const std::vector<double> ledgerZero(2 * n, 0.0);
    fillBuffer(impl_->ledgerCells, static_cast<GLsizeiptr>(ledgerZero.size() * sizeof(double)), ledgerZero.data());
    const double totals[2] = {0.0, 0.0};
    fillBuffer(impl_->totals, sizeof totals, totals);
    gl::throwIfGlError("resetting the water simulation");
}

void GpuWaterSimulation::runSubsteps(const StepConstants& k, long count) {
    const glm::ivec2 grid(width(), height());
    for (auto& p : impl_->programs) {
        p.set(ws::contract::u_gridSize, grid);
        p.set(ws::contract::u_dt, k.dt);
        p.set(ws::contract::u_rainDepth, k.rainDepth);
        p.set(ws::contract::u_openBorder, k.openBorder);
        p.set(ws::contract::u_invEightCell, k.invEightCell);
        p.set(ws::contract::u_flowRateDt, k.flowRateDt);
        p.set(ws::contract::u_maxFlowFraction, k.maxFlowFraction);
        p.set(ws::contract::u_waveAccelDt, k.waveAccelDt);
        p.set(ws::contract::u_damping, k.damping);
        p.set(ws::contract::u_epsilon, k.epsilon);
        p.set(ws::contract::u_capPerDt, k.capPerDt);
        p.set(ws::contract::u_smoothRadius, k.smoothRadius);
        p.set(ws::contract::u_smoothWeights, k.smoothWeights);
        p.set(ws::contract::u_partialCount, static_cast<int>(impl_->partialCount));
    }
    const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
    glBindBufferBase(ssbo, kTerrain, impl_->terrain);
    glBindBufferBase(ssbo, kPermeability, impl_->permeability);
    glBindBufferBase(ssbo, kVelocity, impl_->velocity);
    glBindBufferBase(ssbo, kFlow, impl_->flow);
    glBindBufferBase(ssbo, kLedgerCells, impl_->ledgerCells);
    for (long s = 0; s < count; ++s) {
        impl_->waterPass(kRain);
        impl_->readPass(kFlowOut);
        impl_->waterPass(kFlowGather);
        impl_->readPass(kDistributeVelocity);
        impl_->waterPass(kDistributeApply);
        if (k.smoothRadius > 0) impl_->waterPass(kSmooth);
    }
    glUseProgram(0);
    gl::throwIfGlError("running the water simulation's compute passes");
}

namespace {

template <class T>
std::vector<T> readBuffer(GLuint buffer, std::size_t count) {
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    std::vector<T> out(count);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(T)), out.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return out;
}

}  // namespace

std::vector<glm::vec2> GpuWaterSimulation::depthPairs() const {
    return readBuffer<glm::vec2>(impl_->water[impl_->current], cellCount());
}

std::vector<glm::vec2> GpuWaterSimulation::edgeVelocities() const {
    return readBuffer<glm::vec2>(impl_->velocity, cellCount());
}

void GpuWaterSimulation::lossTotals(double& infiltrated, double& lost) const {
    // Reduce the per-cell double accumulators: one partial per 256 cells, then the total.
    const GLenum ssbo = GL_SHADER_STORAGE_BUFFER;
    glBindBufferBase(ssbo, kLedgerCells, impl_->ledgerCells);
    glBindBufferBase(ssbo, kLedgerPartials, impl_->partials);
    glBindBufferBase(ssbo, kLedgerTotals, impl_->totals);
    impl_->dispatch(kLedgerPartial, impl_->partialCount, 1);
    impl_->dispatch(kLedgerTotal, 1, 1);
    glUseProgram(0);
    const std::vector<double> t = readBuffer<double>(impl_->totals, 2);
    infiltrated = t[0];
    lost = t[1];
}

void GpuWaterSimulation::uploadDepthTexture(unsigned texture) const {
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, impl_->water[impl_->current]);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width(), height(), GL_RG, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

}  // namespace prism::water
