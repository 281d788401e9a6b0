// water: the rain-fed water map on a height-map terrain under a procedural skybox.
//
//   water [--grid N (512)] [--heightmap FILE [--height-scale M]] [--permeability FILE]
//         [--rain CLASS|MM_PER_HOUR] [--steps N] [--dt S] [--gpu] [--fog DENSITY]
//         [--width W] [--height H] [--out DIR]          writes overview.png, ground.png, depth.png
//   water --window [--frames N] ...                       live GLFW viewer (xvfb-run -a headless)
//
//   water --sequence 8 ... --out DIR     8 overview frames, --steps/8 steps apart:
//                                         frame_00.png .. and the strip sequence.png
// A flag the chosen mode would not use (--frames without --window, --height-scale
// without --heightmap, ...) is a usage error: exit 2, never silently ignored.
// Non-finite or out-of-range numbers (--rain 1e46, --dt inf, --cell 0) and a --dt that
// needs more than WaterParams::maxSubsteps substeps are usage errors: exit 2, nothing written.
//
// Window keys: R next rain class (none, drizzle ... cloudburst), Left/Right orbit,
// Up/Down tilt, +/- zoom, F fog on/off, Space pause, Esc quit; the title shows the
// frame time, rain and stored water.
#include <CLI/CLI.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#ifdef PRISM_WATER_HAVE_GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#endif
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/image/contact_sheet.hpp"
#include "prism/image/png_io.hpp"
#include "prism/rain/fog_system.hpp"
#include "prism/rain/rain_programs.hpp"
#include "prism/water/gpu_water_simulation.hpp"
#include "prism/water/rain_rates.hpp"
#include "prism/water/water_scene.hpp"

namespace {

using namespace prism::water;

struct Options {
    int grid = 512;  // the default water map; --window defaults to 128 to stay interactive
    float cellSize = 0.25f;
    std::string heightmap, permeabilityMap;
    float heightScale = 6.0f;
    double permeabilityMaxMmH = 20.0;
    std::string rain = "cloudburst";
    int steps = 300;
    double dt = 1.0;
    bool gpu = false;
    float fog = 0.0f;
    float fogBillboards = 0.0f;  // > 0 (with --fog): soft fog billboards of that strength
    int width = 800, height = 600;
    std::string out = "water-out";
    bool window = false;
    long frames = 0;
    int sequence = 0;  // > 0: that many overview frames and a strip
};

// The flags the chosen mode would not use, as a usage-error message ("" when none).
std::string misplacedFlag(const CLI::App& app, const Options& o) {
    auto given = [&app](const char* flag) { return app.count(flag) > 0; };
    if (o.window) {
        for (const char* f : {"--out", "--steps", "--sequence"})
            if (given(f)) return std::string(f) + " does not apply to --window";
        if (given("--dt") && o.frames == 0)
            return "--dt with --window needs --frames (without it, time follows the clock)";
    } else if (given("--frames")) {
        return "--frames needs --window";
    }
    if (given("--heightmap") && given("--grid"))
        return "--grid makes a procedural terrain; it does not apply to --heightmap";
    if (!given("--heightmap") && given("--height-scale")) return "--height-scale needs --heightmap";
    if (!given("--permeability") && given("--permeability-max")) return "--permeability-max needs --permeability";
    if (given("--fog-billboards") && !(o.fog > 0.0f) && !o.window)
        return "--fog-billboards needs --fog (the billboards are drifting patches of the distance fog)";
    return "";
}

// Top-down map: terrain shaded grey by height, water in blue by depth (log scale).
prism::image::Image8 depthMap(const WaterScene& scene) {
    const HeightField& t = scene.terrain();
    const std::vector<float> depth = scene.water()->simulation().depth();
    const auto [lo, hi] = std::minmax_element(t.heights.begin(), t.heights.end());
    prism::image::Image8 img(t.width, t.height);
    for (int z = 0; z < t.height; ++z)
        for (int x = 0; x < t.width; ++x) {
            const float g = 0.25f + 0.6f * (t.at(x, z) - *lo) / std::max(1e-6f, *hi - *lo);
            const float d = depth[t.index(x, z)];
            const float w =
                d <= 1e-4f ? 0.0f : std::clamp(std::log10(d / 1e-4f) / 3.0f, 0.0f, 1.0f);  // 0.1 mm .. 10 cm
            const float r = g * (1.0f - w) + 0.05f * w, gg = g * (1.0f - w) + 0.25f * w, b = g * (1.0f - w) + 0.85f * w;
            img.set(x, z,
                    {static_cast<std::uint8_t>(r * 255), static_cast<std::uint8_t>(gg * 255),
                     static_cast<std::uint8_t>(b * 255), 255});
        }
    return img;
}

std::string ledgerLine(const WaterSimulation& sim) {
    const MassLedger l = sim.ledger();
    std::ostringstream s;
    s << std::setprecision(6) << "rain in " << l.rainIn * l.cellArea << " m3 = stored " << l.stored * l.cellArea
      << " + infiltrated " << l.infiltrated * l.cellArea << " + lost through the border "
      << l.lostThroughBorder * l.cellArea << " m3; relative error " << std::setprecision(3) << l.relativeError();
    return s.str();
}

WaterSceneDescription describe(const Options& o) {
    WaterSceneDescription d;
    if (!o.heightmap.empty()) {
        d.terrain = loadHeightMap(o.heightmap, {.cellSize = o.cellSize, .heightScale = o.heightScale});
    } else {
        d.terrain = proceduralTerrain({.width = o.grid,
                                       .height = o.grid,
                                       .cellSize = o.cellSize,
                                       .relief = 0.06f * static_cast<float>(o.grid) * o.cellSize,
                                       .seed = 1});
    }
    if (!o.permeabilityMap.empty())
        d.permeability = loadPermeabilityMap(o.permeabilityMap, d.terrain.width, d.terrain.height,
                                             mmPerHourToMetresPerSecond(o.permeabilityMaxMmH));
    d.rainMmPerHour = parseRainRateMmPerHour(o.rain);
    d.backend = o.gpu ? SimulationBackend::Gpu : SimulationBackend::Cpu;
    if (o.fog > 0.0f) d.fog = prism::view::Fog{.color = {0.66f, 0.68f, 0.70f}, .density = o.fog};
    return d;
}

// A bad number on the command line: reported before anything runs or is written; exit 2.
class UsageError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

void requireFinite(double v, const char* flag, const char* range, bool ok) {
    if (!std::isfinite(v) || !ok) {
        std::ostringstream s;
        s << flag << " must be a finite number " << range << " (got " << v << ")";
        throw UsageError(s.str());
    }
}

// Every number the run depends on, and whether the simulated time fits the substep cap
// (WaterParams::maxSubsteps per step; the error names c dt / h and the largest dt).
void checkOptions(const Options& o) {
    requireFinite(o.cellSize, "--cell", "in (0, 10000] m", o.cellSize > 0.0f && o.cellSize <= kMaxCellSize);
    requireFinite(o.heightScale, "--height-scale", "of metres with |scale| <= 1e6",
                  std::abs(o.heightScale) <= kMaxHeight);
    requireFinite(o.permeabilityMaxMmH, "--permeability-max", "of mm/h in [0, 1e6]",
                  o.permeabilityMaxMmH >= 0.0 && o.permeabilityMaxMmH <= 1e6);
    requireFinite(o.dt, "--dt", "of seconds >= 0", o.dt >= 0.0);
    requireFinite(o.fog, "--fog", "per metre in [0, 100]", o.fog >= 0.0f && o.fog <= 100.0f);
    requireFinite(o.fogBillboards, "--fog-billboards", "in [0, 1]", o.fogBillboards >= 0.0f && o.fogBillboards <= 1.0f);
    try {
        parseRainRateMmPerHour(o.rain);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--rain: ") + e.what());
    }
    try {
        planSubsteps(o.dt, WaterParams{}, o.cellSize);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--dt: ") + e.what());
    }
}

// Soft fog billboards over the water scene (RainCL's fog sprites, as JSON scenes with
// "fog": {"billboards": S} draw them): drifting noise patches between 0.5 and 4 m above the
// lowest ground, faded out where they meet the terrain. Built only when asked for.
class FogBillboardLayer {
  public:
    FogBillboardLayer(const WaterScene& scene, const prism::view::Fog& distanceFog, float strength,
                      const glm::vec3& eye)
        : fog_(prism::rain::fogOverGround(
              distanceFog, strength,
              *std::min_element(scene.terrain().heights.begin(), scene.terrain().heights.end()))),
          system_(std::make_unique<prism::rain::FogSystem>(programs_, fog_, eye)) {}
    // Draws into the bound framebuffer, over the water scene drawn there with its depth.
    void draw(const prism::view::Camera& camera, int width, int height, float dt, float timeSeconds) {
        system_->update(dt, camera.eye, glm::vec3(0.0f));
        system_->draw(camera, static_cast<float>(width) / static_cast<float>(std::max(height, 1)), &fog_.distance,
                      timeSeconds);
    }

  private:
    prism::rain::RainPrograms programs_;
    prism::rain::SceneFog fog_;
    std::unique_ptr<prism::rain::FogSystem> system_;
};

// The scene, and the billboards when there are any, as one image.
prism::image::Image8 renderView(WaterSceneRenderer& renderer, FogBillboardLayer* billboards,
                                const prism::view::Camera& camera, int width, int height) {
    if (!billboards) return renderer.renderImage(camera, width, height);
    prism::gl::Framebuffer fb(width, height);
    fb.bind();
    renderer.draw(camera, width, height);
    fb.bind();
    billboards->draw(camera, width, height, 1.0f / 60.0f, 0.0f);
    prism::image::Image8 image = fb.readImage8();
    prism::gl::Framebuffer::bindDefault();
    return image;
}

std::unique_ptr<FogBillboardLayer> billboardsFor(const Options& o, const WaterScene& scene, const glm::vec3& eye) {
    if (!(o.fogBillboards > 0.0f) || !scene.description().fog) return nullptr;
    return std::make_unique<FogBillboardLayer>(scene, *scene.description().fog, o.fogBillboards, eye);
}

// --sequence N: the overview after every steps/N steps (N frames), each render timed, and
// a one-row strip sequence.png.
int runSequence(const Options& o) {
    auto context = prism::gl::createContext({.majorVersion = o.gpu ? 4 : 3, .minorVersion = 3});
    WaterScene scene(describe(o));
    WaterSceneRenderer renderer(scene);
    auto billboards = billboardsFor(o, scene, overviewCamera(scene.terrain()).eye);
    const std::filesystem::path out = o.out;
    std::filesystem::create_directories(out);
    const int stepsPerFrame = std::max(1, o.steps / o.sequence);
    std::vector<prism::image::Image8> frames;
    std::vector<std::string> labels;
    for (int i = 0; i < o.sequence; ++i) {
        for (int k = 0; k < stepsPerFrame; ++k) scene.water()->advance(o.dt);
        const MassLedger ledger = scene.water()->simulation().ledger();
        if (!std::isfinite(ledger.stored)) throw std::runtime_error("the water state is not finite; no more frames");
        const auto t0 = std::chrono::steady_clock::now();
        frames.push_back(renderView(renderer, billboards.get(), overviewCamera(scene.terrain()), o.width, o.height));
        char name[32], label[48];
        std::snprintf(name, sizeof name, "frame_%02d.png", i);
        std::snprintf(label, sizeof label, "t=%.0f s", (i + 1) * stepsPerFrame * o.dt);
        prism::image::writePng(out / name, frames.back());
        labels.emplace_back(label);
        std::cout << "water: wrote " << (out / name).string() << " ("
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s)\n";
    }
    prism::image::writePng(out / "sequence.png", prism::image::composeContactSheet(frames, labels, o.sequence));
    std::cout << "water: wrote " << (out / "sequence.png").string() << "\n";
    return 0;
}

int runOffscreen(const Options& o) {
    if (o.sequence > 0) return runSequence(o);
    // Drawing needs GL 3.3; the compute-shader step 4.3.
    auto context = prism::gl::createContext({.majorVersion = o.gpu ? 4 : 3, .minorVersion = 3});
    WaterScene scene(describe(o));
    std::cout << "water: " << scene.terrain().width << "x" << scene.terrain().height << " cells of "
              << scene.terrain().cellSize << " m, rain " << scene.description().rainMmPerHour << " mm/h, "
              << (o.gpu ? "GPU (compute shaders)" : "CPU") << " step, " << o.steps << " steps of " << o.dt << " s\n";
    const auto start = std::chrono::steady_clock::now();
    long substeps = 0;
    for (int i = 0; i < o.steps; ++i) substeps += scene.water()->advance(o.dt).count;
    if (o.gpu) glFinish();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "water: " << substeps << " substeps in " << seconds << " s (" << 1e3 * seconds / std::max(1L, substeps)
              << " ms each)\n";
    std::cout << "water: " << ledgerLine(scene.water()->simulation()) << "\n";
    const MassLedger ledger = scene.water()->simulation().ledger();
    if (!std::isfinite(ledger.stored) || !std::isfinite(ledger.relativeError()))
        throw std::runtime_error("the water state is not finite; no images written");
    WaterSceneRenderer renderer(scene);
    auto billboards = billboardsFor(o, scene, overviewCamera(scene.terrain()).eye);
    const std::filesystem::path out = o.out;
    std::filesystem::create_directories(out);
    prism::image::writePng(out / "overview.png",
                           renderView(renderer, billboards.get(), overviewCamera(scene.terrain()), o.width, o.height));
    prism::image::writePng(out / "ground.png",
                           renderView(renderer, billboards.get(), groundCamera(scene.terrain()), o.width, o.height));
    prism::image::writePng(out / "depth.png", depthMap(scene));
    std::cout << "water: wrote " << (out / "overview.png").string() << ", ground.png and depth.png\n";
    return 0;
}

#ifdef PRISM_WATER_HAVE_GLFW
struct ViewState {
    float yaw = 0.9f, pitch = 0.55f, zoom = 1.0f;
    int rainIndex = 6;  // 0 none, 1..6 the RainCL Table 2 classes
    bool rainChanged = false, fogToggled = false, paused = false;
};

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_RELEASE) return;
    auto& s = *static_cast<ViewState*>(glfwGetWindowUserPointer(window));
    switch (key) {
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
        case GLFW_KEY_LEFT: s.yaw -= 0.1f; break;
        case GLFW_KEY_RIGHT: s.yaw += 0.1f; break;
        case GLFW_KEY_UP: s.pitch = std::min(1.45f, s.pitch + 0.05f); break;
        case GLFW_KEY_DOWN: s.pitch = std::max(0.05f, s.pitch - 0.05f); break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD: s.zoom *= 0.9f; break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT: s.zoom *= 1.1f; break;
        case GLFW_KEY_R:
            s.rainIndex = (s.rainIndex + 1) % 7;
            s.rainChanged = true;
            break;
        case GLFW_KEY_F: s.fogToggled = true; break;
        case GLFW_KEY_SPACE: s.paused = !s.paused; break;
        default: break;
    }
}

// What the keys changed since the last frame: the rain class (R) and the fog (F).
void applyKeyChanges(ViewState& state, WaterScene& scene, const prism::view::Fog& fog) {
    if (state.rainChanged) {
        const double mmh = state.rainIndex == 0
                               ? 0.0
                               : rainRateMmPerHour(rainClassTable()[static_cast<std::size_t>(state.rainIndex - 1)].id);
        scene.water()->setRain(mmh);
        state.rainChanged = false;
    }
    if (state.fogToggled) {  // the renderer switches to the FOG=0 / FOG=1 programs
        scene.setFog(scene.description().fog ? std::nullopt : std::optional<prism::view::Fog>(fog));
        state.fogToggled = false;
    }
}

std::string windowTitle(const WaterScene& scene, const ViewState& state, double smoothedMs) {
    const HeightField& t = scene.terrain();
    std::ostringstream title;
    title << std::fixed << std::setprecision(1) << "Prism water - " << smoothedMs << " ms - rain "
          << scene.water()->rainMmPerHour() << " mm/h - stored " << std::setprecision(3)
          << scene.water()->simulation().ledger().stored * t.cellSize * t.cellSize << " m3"
          << (state.paused ? " (paused)" : "");
    return title.str();
}

int runWindow(const Options& o) {
    prism::gl::ContextOptions co;
    co.majorVersion = o.gpu ? 4 : 3;
    co.minorVersion = 3;
    co.width = o.width;
    co.height = o.height;
    co.windowTitle = "Prism water";
    co.vsync = o.frames == 0;
    auto context = prism::gl::createContext(prism::gl::Backend::Glfw, co);
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    ViewState state;
    for (std::size_t i = 0; i < rainClassTable().size(); ++i)
        if (auto c = parseRainClass(o.rain); c && *c == rainClassTable()[i].id)
            state.rainIndex = static_cast<int>(i) + 1;
    if (parseRainRateMmPerHour(o.rain) == 0.0) state.rainIndex = 0;
    glfwSetWindowUserPointer(window, &state);
    glfwSetKeyCallback(window, onKey);
    WaterSceneDescription d = describe(o);
    const prism::view::Fog fog{.color = {0.66f, 0.68f, 0.70f}, .density = o.fog > 0.0f ? o.fog : 0.012f};
    d.fog = fog;
    auto scene = std::make_unique<WaterScene>(std::move(d));
    auto renderer = std::make_unique<WaterSceneRenderer>(*scene);
    auto billboards = billboardsFor(o, *scene, overviewCamera(scene->terrain()).eye);
    const HeightField& t = scene->terrain();
    const float extent = std::max(t.sizeX(), t.sizeZ());
    double smoothedMs = 0.0;
    auto last = std::chrono::steady_clock::now();
    for (long frame = 0; !context->shouldClose() && (o.frames == 0 || frame < o.frames); ++frame) {
        const auto now = std::chrono::steady_clock::now();
        const double wall = std::min(0.1, std::chrono::duration<double>(now - last).count());
        last = now;
        applyKeyChanges(state, *scene, fog);
        // 60x accelerated time so puddles form while you watch.
        if (!state.paused) scene->advance(o.frames ? o.dt : 60.0 * wall);
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        prism::view::Camera cam = overviewCamera(t);
        const float r = 1.1f * extent * state.zoom;
        cam.eye = {r * std::cos(state.pitch) * std::sin(state.yaw), cam.target.y + r * std::sin(state.pitch),
                   r * std::cos(state.pitch) * std::cos(state.yaw)};
        prism::gl::Framebuffer::bindDefault();
        renderer->draw(cam, std::max(w, 1), std::max(h, 1));
        if (billboards && scene->description().fog) {  // F turns the fog, billboards included, off
            prism::gl::Framebuffer::bindDefault();
            billboards->draw(cam, std::max(w, 1), std::max(h, 1), static_cast<float>(wall),
                             static_cast<float>(std::chrono::duration<double>(now.time_since_epoch()).count()));
        }
        glFinish();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - now).count();
        smoothedMs = frame == 0 ? ms : 0.9 * smoothedMs + 0.1 * ms;
        glfwSetWindowTitle(window, windowTitle(*scene, state, smoothedMs).c_str());
        context->swapBuffers();
        context->pollEvents();
    }
    std::cout << "water: last frame " << smoothedMs << " ms (smoothed); " << ledgerLine(scene->water()->simulation())
              << "\n";
    renderer.reset();
    scene.reset();
    return 0;
}
#endif

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Rain-fed water on a height-map terrain: simulate and write PNG views, or --window"};
    Options o;
    app.add_option("--grid", o.grid, "procedural terrain of N x N cells")->check(CLI::Range(1, 8192));
    app.add_option("--cell", o.cellSize, "metres per cell, in (0, 10000]");
    app.add_option("--heightmap", o.heightmap, "8- or 16-bit PNG height map instead of the procedural terrain");
    app.add_option("--height-scale", o.heightScale, "metres for the brightest height-map value");
    app.add_option("--permeability", o.permeabilityMap, "8- or 16-bit PNG permeability (attribute) map");
    app.add_option("--permeability-max", o.permeabilityMaxMmH,
                   "infiltration rate (mm/h) of a white permeability pixel");
    app.add_option("--rain", o.rain,
                   "rain class (drizzle, light, moderate, heavy, excessive, cloudburst), none, or mm/h");
    app.add_option("--steps", o.steps, "simulation steps")->check(CLI::NonNegativeNumber);
    app.add_option("--dt", o.dt, "seconds per step (split into stable substeps)")->check(CLI::NonNegativeNumber);
    app.add_flag("--gpu", o.gpu, "run the step as compute shaders (GL 4.3)");
    app.add_option("--fog", o.fog, "fog density per metre (0: no fog)")->check(CLI::NonNegativeNumber);
    app.add_option("--fog-billboards", o.fogBillboards, "soft fog billboards of this strength in (0, 1] (needs --fog)")
        ->check(CLI::Range(0.0f, 1.0f));
    app.add_option("--width", o.width, "image width")->check(CLI::Range(1, 8192));
    app.add_option("--height", o.height, "image height")->check(CLI::Range(1, 8192));
    app.add_option("--out", o.out, "output directory");
    app.add_flag("--window", o.window, "open the live GLFW viewer");
    app.add_option("--frames", o.frames, "with --window: quit after N frames");
    app.add_option("--sequence", o.sequence, "write N overview frames, --steps/N steps apart, and a strip")
        ->check(CLI::Range(1, 64));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int rc = app.exit(e);  // prints help or the error
        return rc == 0 ? 0 : 2;      // usage errors exit 2
    }
    if (o.window && app.count("--grid") == 0) o.grid = 128;
    try {
        checkOptions(o);
    } catch (const UsageError& e) {
        std::cerr << "water: error: " << e.what() << "\n";
        return 2;
    }
    if (const std::string m = misplacedFlag(app, o); !m.empty()) {
        std::cerr << "water: error: " << m << "\n";
        return 2;
    }
    try {
        if (o.window) {
#ifdef PRISM_WATER_HAVE_GLFW
            return runWindow(o);
#else
            std::cerr << "water: this build has no GLFW; install libglfw3-dev and reconfigure\n";
            return 1;
#endif
        }
        return runOffscreen(o);
    } catch (const std::exception& e) {
        std::cerr << "water: error: " << e.what() << "\n";
        return 1;
    }
}
