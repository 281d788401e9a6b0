// The rain-fed water map of RainCL (Bruder 2013, §4.2): a grid over the terrain whose
// cells hold a water depth and a velocity, advanced by a fixed sequence of steps. Two
// implementations run the same step: CpuWaterSimulation (the reference) and
// GpuWaterSimulation (compute shaders, gpu_water_simulation.hpp).
//
// Usage (snippet: examples/snippets/water_water_simulation.cpp):
//
//     #include "prism/water/water_simulation.hpp"
//     using namespace prism::water;
//     HeightField terrain = proceduralTerrain({.width = 128, .height = 128});
//     CpuWaterSimulation sim(terrain, proceduralPermeability(terrain), WaterParams{});
//     sim.setRainRate(mmPerHourToMetresPerSecond(rainRateMmPerHour(RainClass::Heavy)));
//     SubstepPlan plan = sim.advance(0.5);     // 0.5 s, split into plan.count substeps
//     std::vector<float> depth = sim.depth();  // metres per cell
//     MassLedger l = sim.ledger();             // rain in = stored + infiltrated + lost
//
// One substep of length dt, in this order (the step is written in flux form: every
// transfer between two cells is computed identically by both, so what one loses the
// other gains exactly, and no transfer takes more than a cell has):
//  1. rain: every cell gains rainRate x dt;
//  2. infiltration: a cell loses permeability x dt, or all its water when that is as
//     much (emptied exactly, never below zero);
//  3. tangential flow (RainCL §4.2.4): the Sobel gradient of the free surface (terrain +
//     water) picks the downhill Moore neighbour; a cell sends min(maxFlowFraction,
//     flowRate x dt x |slope|) of its water there, at most half the surface drop; with
//     an open border, water aimed outside the grid leaves (lost through the border);
//  4. distribution (RainCL §4.2.5, Algorithm 1, after Mueller's height-field fluid, per von
//     Neumann edge): q += c^2/h^2 (s_a - s_b) dt, q *= exp(-damping dt); the epsilon rule
//     stops an edge whose receiver stands >= epsilon above the giver's surface; each
//     edge moves q dt, at most a quarter of the giver's water;
//  5. Gaussian smoothing of the free surface (normalised kernel of size 2r+1, strength
//     min(1, smoothingRate dt)), as pairwise exchanges limited by the giver's water.
// The water depth is stored as a compensated pair of fp32 numbers (hi + lo, see
// modules/water/water_grid.glsl) so that small rain increments on deep water are not
// rounded away; both implementations use fp32 arithmetic in the same order.
//
// Stability: the distribution is explicit (symplectic Euler) and stable only for
// c dt / h <= 1/sqrt(2). advance(dt) splits dt into n = ceil(dt / dtMax) equal substeps
// with dtMax = courantNumber x h / c (courantNumber <= 1/sqrt(2), default 0.7), at most
// maxSubsteps (default kDefaultMaxSubsteps) per call.
//
// Heights: the simulation keeps the terrain relative to a whole-metre local origin at or
// below its lowest point (terrain().origin holds the offset), so surfaces are computed in
// fp32 near zero: the same terrain 3000 m higher gives the same depths.
#pragma once

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "prism/water/height_field.hpp"

namespace prism::water {

// Which implementation runs the step: the CPU reference, the compute shaders, or the faster
// of the two on the current renderer, measured once (prism/water/backend_choice.hpp).
enum class SimulationBackend { Cpu, Gpu, Fastest };
std::string_view simulationBackendName(SimulationBackend backend);               // "cpu", "gpu", "fastest"
std::optional<SimulationBackend> parseSimulationBackend(std::string_view name);  // one of those names

enum class BorderMode {
    Open,    // tangential flow carries water off the map (the ledger's "lost through the border")
    Closed,  // RainCL's rule (§4.2.4): no tangent at the border, water stays on the map
};

// The default cap on substeps per advance() call: 100,000 (about 10 minutes of the 512²
// CPU step). A dt needing more is an error that names the stability limit c dt / h and the
// largest dt one call can take, instead of a run that looks like a hang.
inline constexpr long kDefaultMaxSubsteps = 100'000;
// The largest rain rate the simulation accepts: 10,000 mm/h (rain_rates.hpp), in m/s.
inline constexpr double kMaxRainMetresPerSecond = 10000.0 / 1000.0 / 3600.0;

struct WaterParams {
    float waveSpeed = 0.5f;         // c, m/s, of the distribution's height-field waves
    float courantNumber = 0.7f;     // c dt / h of a substep; at most 1/sqrt(2) = 0.7071
    float dampingPerSecond = 2.0f;  // edge velocity factor exp(-damping dt) per substep
    float epsilon = 0.002f;         // m, the epsilon of RainCL Algorithm 1
    float flowRate = 4.0f;          // 1/s per unit slope, tangential flow
    float maxFlowFraction = 0.5f;   // at most this share of a cell's water per tangential step
    int smoothingKernel = 5;        // odd, 1..15; 1 switches smoothing off
    float smoothingSigma = 1.0f;    // cells
    float smoothingRate = 1.0f;     // 1/s: strength per substep = min(1, rate dt)
    BorderMode border = BorderMode::Open;
    int threads = 0;                         // CPU step: row bands on this many threads, 0 = all cores (1..64); the
                                             // result is the same for every count (grids under 128^2 use one)
    long maxSubsteps = kDefaultMaxSubsteps;  // advance() refuses a dt needing more
};

// Throws std::invalid_argument naming the first unusable parameter.
void validate(const WaterParams& params);

// The largest stable substep for these parameters and cell size: courantNumber h / c.
double maxStableDt(const WaterParams& params, float cellSize);

struct SubstepPlan {
    long count = 0;   // 0 for dt == 0
    double dt = 0.0;  // length of each substep, seconds
};
// Throws std::invalid_argument for a negative or non-finite dt, or one needing more
// than params.maxSubsteps substeps.
SubstepPlan planSubsteps(double dt, const WaterParams& params, float cellSize);

// The fp32 constants of one substep, computed once in double and rounded: both
// implementations receive exactly these values.
struct StepConstants {
    float dt = 0, rainDepth = 0, invEightCell = 0, flowRateDt = 0, maxFlowFraction = 0;
    float waveAccelDt = 0, damping = 1, epsilon = 0, capPerDt = 0;
    int openBorder = 1;
    int smoothRadius = 0;
    std::array<float, 64> smoothWeights{};  // [|dz| * 8 + |dx|] = strength g(dx) g(dz)
};
StepConstants stepConstants(const WaterParams& params, float cellSize, double dt, double rainRate);

// The normalised 1D Gaussian of `kernel` taps (odd) and `sigma`: radius + 1 weights from
// the centre outwards; sum over all taps is 1.
std::vector<double> gaussianWeights(int kernel, float sigma);

// Water volumes, as sums of depths over cells (multiply by cellArea for cubic metres).
struct MassLedger {
    double initial = 0.0;  // water present when the ledger started (setDepth)
    double rainIn = 0.0;   // rain added: per substep the fp32 rain depth (rate x dt, within
                           // 2^-24 of the exact product) x cells, accumulated in double
    double infiltrated = 0.0;
    double lostThroughBorder = 0.0;
    double stored = 0.0;    // sum of the current depths
    double cellArea = 1.0;  // m^2 per cell

    // (initial + rain in) - (stored + infiltrated + lost); zero for perfect conservation.
    double imbalance() const { return initial + rainIn - (stored + infiltrated + lostThroughBorder); }
    // |imbalance| relative to everything that entered (initial + rain), 0 when nothing did.
    double relativeError() const;
};

class WaterSimulation {
  public:
    virtual ~WaterSimulation() = default;
    WaterSimulation(const WaterSimulation&) = delete;
    WaterSimulation& operator=(const WaterSimulation&) = delete;

    int width() const { return terrain_.width; }
    int height() const { return terrain_.height; }
    std::size_t cellCount() const { return terrain_.cellCount(); }
    const HeightField& terrain() const { return terrain_; }
    const std::vector<float>& permeability() const { return permeability_; }
    const WaterParams& params() const { return params_; }

    // Rain rate in m/s, finite, in [0, kMaxRainMetresPerSecond]; applies to the following
    // advance() calls. Throws std::invalid_argument otherwise.
    void setRainRate(double metresPerSecond);
    double rainRate() const { return rainRate_; }

    // Advances by dt seconds in planSubsteps(dt) substeps; returns the plan.
    SubstepPlan advance(double dt);
    // Runs `count` substeps with these constants exactly as given, without planSubsteps()
    // and its stability bound: for experiments such as the test that shows the bound.
    // The ledger counts k.rainDepth per cell and substep as rain.
    void advanceWithConstants(const StepConstants& constants, long count);
    long substepsDone() const { return substeps_; }
    double simulatedTime() const { return time_; }

    // Replaces the water (depths >= 0, one per cell), clears velocities and restarts the
    // ledger with this water as its initial amount.
    void setDepth(std::span<const float> depth);
    // Depth per cell in metres (hi + lo of the compensated pair, rounded to fp32).
    std::vector<float> depth() const;
    // The compensated pairs (hi, lo) per cell.
    virtual std::vector<glm::vec2> depthPairs() const = 0;
    // Velocity of each cell's east (x) and south (y) edge, m/s of depth change.
    virtual std::vector<glm::vec2> edgeVelocities() const = 0;
    MassLedger ledger() const;

    virtual std::string_view backendName() const = 0;

  protected:
    WaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params);
    virtual void runSubsteps(const StepConstants& constants, long count) = 0;
    virtual void resetState(std::span<const glm::vec2> depthPairs) = 0;
    // Totals of infiltrated and border-lost depth since the last resetState().
    virtual void lossTotals(double& infiltrated, double& lost) const = 0;

    HeightField terrain_;
    std::vector<float> permeability_;
    WaterParams params_;

  private:
    double rainRate_ = 0.0;
    double rainIn_ = 0.0;
    double initial_ = 0.0;
    double time_ = 0.0;
    long substeps_ = 0;
};

namespace detail {
class RowBands;
}

// The CPU reference: fp32 in the GPU's order, denormals flushed to zero during a step as
// Mesa's llvmpipe does. A substep runs its passes fused row by row (the intermediate water
// in per-thread rings of rows) over row bands on WaterParams::threads threads, with one
// barrier per substep; every cell is computed with the same operations in the same order
// whatever the thread count, so the depths are bit-identical to one thread (and to the
// plain per-pass, per-cell loops of the first version, kept as the test reference in
// tests/water/reference_water_step.cpp). The ledger's double sums are taken per row, then
// over rows: within 1e-12 relative of a single running sum.
class CpuWaterSimulation final : public WaterSimulation {
  public:
    CpuWaterSimulation(HeightField terrain, std::vector<float> permeability, WaterParams params = {});
    ~CpuWaterSimulation() override;
    // The threads the step runs on (threadsFor(params.threads, cells)).
    int threads() const { return threads_; }
    // Bytes a substep would read and write per cell if each pass streamed every array it
    // touches once (neighbour reads from cache): 180 with smoothing, 144 without. The
    // memory floor of bench/water is cells x this / copy bandwidth.
    static int bytesPerCellPerSubstep(bool smoothing);
    // Bytes the fused step streams per cell and substep: its state in and out (40).
    static int bytesStreamedPerCellPerSubstep();

    std::vector<glm::vec2> depthPairs() const override;
    std::vector<glm::vec2> edgeVelocities() const override;
    std::string_view backendName() const override { return "cpu"; }

  protected:
    void runSubsteps(const StepConstants& constants, long count) override;
    void resetState(std::span<const glm::vec2> depthPairs) override;
    void lossTotals(double& infiltrated, double& lost) const override;

  private:
    void substep(const StepConstants& k);

    // The state (compensated depth pairs, edge velocities) and the next substep's.
    std::vector<float> hi_, lo_, qEast_, qSouth_, hiNext_, loNext_, qEastNext_, qSouthNext_;
    std::vector<double> infiltratedRow_, lostRow_;
    double infiltrated_ = 0.0, lost_ = 0.0;
    int threads_ = 1;
    std::unique_ptr<detail::RowBands> bands_;
};

}  // namespace prism::water
