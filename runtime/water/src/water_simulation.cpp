// Parameters, substep planning, step constants and the ledger of the water map (see
// water_simulation.hpp); the step itself is in cpu_water_simulation.cpp and the
// compute shaders.
#include "prism/water/water_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace prism::water {
namespace {

[[noreturn]] void bad(const std::string& what) {
    throw std::invalid_argument("WaterParams: " + what);
}

bool finite(double v) {
    return std::isfinite(v);
}

}  // namespace

void validate(const WaterParams& p) {
    if (!(p.waveSpeed > 0.0f) || !finite(p.waveSpeed)) bad("waveSpeed must be a finite number > 0 (m/s)");
    if (!(p.courantNumber > 0.0f) || p.courantNumber > 0.70710678f)
        bad("courantNumber must lie in (0, 1/sqrt(2) = 0.7071]: the height-field distribution is unstable above "
            "(got " +
            std::to_string(p.courantNumber) + ")");
    if (!(p.dampingPerSecond >= 0.0f) || !finite(p.dampingPerSecond)) bad("dampingPerSecond must be >= 0");
    if (!(p.epsilon >= 0.0f) || !finite(p.epsilon)) bad("epsilon must be >= 0 (m)");
    if (!(p.flowRate >= 0.0f) || !finite(p.flowRate)) bad("flowRate must be >= 0 (1/s)");
    if (!(p.maxFlowFraction >= 0.0f) || p.maxFlowFraction > 1.0f) bad("maxFlowFraction must lie in [0, 1]");
    if (p.smoothingKernel < 1 || p.smoothingKernel > 15 || p.smoothingKernel % 2 == 0)
        bad("smoothingKernel must be odd and in 1..15 (got " + std::to_string(p.smoothingKernel) + ")");
    if (!(p.smoothingSigma > 0.0f) || !finite(p.smoothingSigma)) bad("smoothingSigma must be > 0 (cells)");
    if (!(p.smoothingRate >= 0.0f) || !finite(p.smoothingRate)) bad("smoothingRate must be >= 0 (1/s)");
    if (p.maxSubsteps < 1) bad("maxSubsteps must be >= 1");
    if (p.threads < 0 || p.threads > 64)
        bad("threads must be in 0..64 (0: all cores; got " + std::to_string(p.threads) + ")");
}

double maxStableDt(const WaterParams& p, float cellSize) {
    validate(p);
    if (!(cellSize > 0.0f) || !(cellSize <= kMaxCellSize))
        throw std::invalid_argument("maxStableDt: the cell size must be a finite number in (0, " +
                                    std::to_string(kMaxCellSize) + "] m (got " + std::to_string(cellSize) + ")");
    return static_cast<double>(p.courantNumber) * static_cast<double>(cellSize) / static_cast<double>(p.waveSpeed);
}

SubstepPlan planSubsteps(double dt, const WaterParams& p, float cellSize) {
    if (!(dt >= 0.0) || !finite(dt))
        throw std::invalid_argument("water step: dt must be a finite number of seconds >= 0 (got " +
                                    std::to_string(dt) + ")");
    const double dtMax = maxStableDt(p, cellSize);
    if (dt == 0.0) return {};
    const double n = std::ceil(dt / dtMax);
    if (n > static_cast<double>(p.maxSubsteps)) {
        std::ostringstream s;
        s << "water step: dt = " << dt << " s needs " << n << " substeps, more than maxSubsteps = " << p.maxSubsteps
          << ". The height-field distribution is stable only while c dt / h <= 1/sqrt(2) (here c = " << p.waveSpeed
          << " m/s, h = " << cellSize << " m, courantNumber = " << p.courantNumber
          << "), so the largest stable substep is courantNumber h / c = " << dtMax
          << " s and one advance() can take at most maxSubsteps x " << dtMax << " = "
          << dtMax * static_cast<double>(p.maxSubsteps)
          << " s. Advance in shorter calls, use a larger cell size or a lower waveSpeed, or raise maxSubsteps.";
        throw std::invalid_argument(s.str());
    }
    return {static_cast<long>(n), dt / n};
}

std::vector<double> gaussianWeights(int kernel, float sigma) {
    const int r = (kernel - 1) / 2;
    std::vector<double> g(static_cast<std::size_t>(r + 1));
    double sum = 0.0;
    for (int k = 0; k <= r; ++k) {
        g[static_cast<std::size_t>(k)] = std::exp(-0.5 * k * k / (static_cast<double>(sigma) * sigma));
        sum += (k == 0 ? 1.0 : 2.0) * g[static_cast<std::size_t>(k)];
    }
    for (double& v : g) v /= sum;
    return g;
}

StepConstants stepConstants(const WaterParams& p, float cellSize, double dt, double rainRate) {
    validate(p);
    const double h = cellSize, c = p.waveSpeed;
    StepConstants k;
    k.dt = static_cast<float>(dt);
    k.rainDepth = static_cast<float>(rainRate * dt);
    k.invEightCell = static_cast<float>(1.0 / (8.0 * h));
    k.flowRateDt = static_cast<float>(static_cast<double>(p.flowRate) * dt);
    k.maxFlowFraction = p.maxFlowFraction;
    k.waveAccelDt = static_cast<float>(c * c / (h * h) * dt);
    k.damping = static_cast<float>(std::exp(-static_cast<double>(p.dampingPerSecond) * dt));
    k.epsilon = p.epsilon;
    k.capPerDt = dt > 0.0 ? static_cast<float>(0.24 / dt) : 0.0f;
    k.openBorder = p.border == BorderMode::Open ? 1 : 0;
    const double strength = std::min(1.0, static_cast<double>(p.smoothingRate) * dt);
    k.smoothRadius = (p.smoothingKernel > 1 && strength > 0.0) ? (p.smoothingKernel - 1) / 2 : 0;
    if (k.smoothRadius > 0) {
        const std::vector<double> g = gaussianWeights(p.smoothingKernel, p.smoothingSigma);
        for (int dz = 0; dz <= k.smoothRadius; ++dz)
            for (int dx = 0; dx <= k.smoothRadius; ++dx)
                k.smoothWeights[static_cast<std::size_t>(dz * 8 + dx)] =
                    static_cast<float>(strength * g[static_cast<std::size_t>(dx)] * g[static_cast<std::size_t>(dz)]);
    }
    return k;
}

double MassLedger::relativeError() const {
    const double in = initial + rainIn;
    return in > 0.0 ? std::abs(imbalance()) / in : std::abs(imbalance());
}

WaterSimulation::WaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params)
    : terrain_(std::move(terrain)), permeability_(std::move(permeability)), params_(params) {
    validate(terrain_, "water simulation terrain");
    validate(params_);
    // A whole-metre local origin at or below the lowest point: heights in [0, relief + 1).
    // A terrain already there (lowest point in [0, 1) m) is left bit for bit as it is.
    const double shift =
        std::floor(static_cast<double>(*std::min_element(terrain_.heights.begin(), terrain_.heights.end())));
    if (shift != 0.0) {
        for (float& h : terrain_.heights) h = static_cast<float>(static_cast<double>(h) - shift);
        terrain_.origin += shift;
    }
    if (permeability_.empty()) permeability_.assign(terrain_.cellCount(), 0.0f);
    if (permeability_.size() != terrain_.cellCount())
        throw std::invalid_argument("water simulation: " + std::to_string(permeability_.size()) +
                                    " permeability values for " + std::to_string(terrain_.cellCount()) + " cells");
    for (float k : permeability_)
        if (!(k >= 0.0f) || !std::isfinite(k))
            throw std::invalid_argument("water simulation: permeability must be finite and >= 0 (m/s)");
}

void WaterSimulation::setRainRate(double metresPerSecond) {
    if (!(metresPerSecond >= 0.0) || !(metresPerSecond <= kMaxRainMetresPerSecond)) {
        std::ostringstream s;
        s << "water simulation: the rain rate must be a finite number of m/s in [0, " << kMaxRainMetresPerSecond
          << "] (10000 mm/h) (got " << metresPerSecond << ")";
        throw std::invalid_argument(s.str());
    }
    rainRate_ = metresPerSecond;
}

SubstepPlan WaterSimulation::advance(double dt) {
    const SubstepPlan plan = planSubsteps(dt, params_, terrain_.cellSize);
    if (plan.count == 0) return plan;
    const StepConstants k = stepConstants(params_, terrain_.cellSize, plan.dt, rainRate_);
    runSubsteps(k, plan.count);
    // The rain the model adds: rate x dt rounded once to fp32 (within 2^-24 of the exact
    // product), then summed in double.
    rainIn_ += static_cast<double>(k.rainDepth) * static_cast<double>(plan.count) * static_cast<double>(cellCount());
    time_ += dt;
    substeps_ += plan.count;
    return plan;
}

void WaterSimulation::advanceWithConstants(const StepConstants& k, long count) {
    if (count <= 0) return;
    runSubsteps(k, count);
    rainIn_ += static_cast<double>(k.rainDepth) * static_cast<double>(count) * static_cast<double>(cellCount());
    time_ += static_cast<double>(k.dt) * static_cast<double>(count);
    substeps_ += count;
}

void WaterSimulation::setDepth(std::span<const float> depth) {
    if (depth.size() != cellCount())
        throw std::invalid_argument("water simulation: setDepth got " + std::to_string(depth.size()) + " depths for " +
                                    std::to_string(cellCount()) + " cells");
    std::vector<glm::vec2> pairs(depth.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < depth.size(); ++i) {
        if (!(depth[i] >= 0.0f) || !std::isfinite(depth[i]))
            throw std::invalid_argument("water simulation: depths must be finite and >= 0");
        pairs[i] = {depth[i], 0.0f};
        sum += depth[i];
    }
    resetState(pairs);
    initial_ = sum;
    rainIn_ = 0.0;
}

std::vector<float> WaterSimulation::depth() const {
    const std::vector<glm::vec2> pairs = depthPairs();
    std::vector<float> d(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i) d[i] = pairs[i].x + pairs[i].y;
    return d;
}

MassLedger WaterSimulation::ledger() const {
    MassLedger l;
    l.initial = initial_;
    l.rainIn = rainIn_;
    lossTotals(l.infiltrated, l.lostThroughBorder);
    for (const glm::vec2& w : depthPairs()) l.stored += static_cast<double>(w.x) + static_cast<double>(w.y);
    l.cellArea = static_cast<double>(terrain_.cellSize) * terrain_.cellSize;
    return l;
}

std::string_view simulationBackendName(SimulationBackend backend) {
    switch (backend) {
        case SimulationBackend::Cpu: return "cpu";
        case SimulationBackend::Gpu: return "gpu";
        case SimulationBackend::Fastest: return "fastest";
    }
    return "?";
}

std::optional<SimulationBackend> parseSimulationBackend(std::string_view name) {
    for (SimulationBackend b : {SimulationBackend::Cpu, SimulationBackend::Gpu, SimulationBackend::Fastest})
        if (simulationBackendName(b) == name) return b;
    return std::nullopt;
}

}  // namespace prism::water
