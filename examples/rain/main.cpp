// prism-rain: the rain scene of docs/rain.md as PNG images from a fixed seed, or live.
//
//   prism-rain [--out DIR]                       the standard shots + a contact sheet
//   prism-rain --view 0 --intensity heavy --wind 6 --fog --out DIR   one image, rain.png
//   prism-rain --window                          a GLFW window (xvfb-run -a when headless)
//       I / K   heavier / lighter rain (the six classes of RainCL Table 2)
//       W       stronger wind (+2 m/s, back to calm after 12); Shift+W turns it by 45 deg
//       F       fog on/off (the scene is rebuilt: no fog programs without fog)
//       T       next streak technique (gs-quads, instanced-quads, point-sprites)
//       Left/Right  turn the camera      Up/Down  walk      Esc  quit
//   --frames N quits after N frames (tests); --demo-keys presses I, K, W, F, T once each.
//   prism-rain --sequence 8 [--view V] --out DIR   8 frames 1/30 s apart: frame_00.png ..
//                                                  and the strip sequence.png
// A flag that does not apply to the chosen mode is a usage error (exit 2), never ignored.
#include <CLI/CLI.hpp>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#if PRISM_RAIN_HAVE_GLFW
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#endif
#include "prism/image/contact_sheet.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/image/png_io.hpp"
#include "prism/rain/rain_scene.hpp"

namespace {

namespace fs = std::filesystem;
using namespace prism::rain;

struct Options {
    std::string out = "rain-images";
    std::uint32_t seed = 2013;
    int width = 800;
    int height = 800;
    int warmup = 30;
    std::string intensity = "moderate";
    float wind = 0.0f;
    float windDirection = 200.0f;
    bool fog = false;
    float fogStrength = 0.45f;
    std::string technique = "gs";
    int view = -1;
    bool window = false;
    long frames = 0;
    bool demoKeys = false;
    int sequence = 0;  // > 0: that many consecutive frames and a strip
};

// The flags the chosen mode would not use, as a usage-error message ("" when none).
std::string misplacedFlag(const CLI::App& app, const Options& o) {
    auto given = [&app](const char* flag) { return app.count(flag) > 0; };
    if (o.window) {
        for (const char* f : {"--out", "--view", "--warmup", "--sequence"})
            if (given(f)) return std::string(f) + " does not apply to --window";
        if (!parseRainClass(o.intensity)) return "with --window, --intensity must name a class (drizzle..cloudburst)";
    } else {
        for (const char* f : {"--frames", "--demo-keys"})
            if (given(f)) return std::string(f) + " needs --window";
        if (o.view < 0 && o.sequence == 0)
            for (const char* f : {"--intensity", "--wind", "--fog", "--fog-strength"})
                if (given(f))
                    return std::string(f) + " needs --view, --sequence or --window (the standard shots fix their own " +
                           "rain, wind and fog)";
    }
    if (given("--fog-strength") && !o.fog) return "--fog-strength needs --fog";
    return "";
}

float parseIntensity(const std::string& text) {
    if (auto c = parseRainClass(text)) return rainClassInfo(*c).intensity;
    std::optional<float> number;
    try {
        std::size_t used = 0;
        const float v = std::stof(text, &used);
        if (used == text.size()) number = v;
    } catch (const std::exception&) {
    }
    if (number) {
        validateIntensity(*number);  // names the bad value and the range
        return *number;
    }
    throw RainParameterError(
        "rain: --intensity must be drizzle, light, moderate, heavy, excessive, cloudburst or a "
        "number of cm/h >= 0 (got '" +
        text + "')");
}

RainSceneDesc sceneFor(const Options& o, int view, float intensity, float wind, bool fog) {
    RainSceneDesc d = defaultRainScene();
    d.camera = rainSceneView(view);
    d.rain->seed = o.seed;
    d.rain->intensity = intensity;
    d.rain->wind.strength = wind;
    d.rain->wind.directionDegrees = o.windDirection;
    if (fog) {
        SceneFog f;
        f.billboards.strength = o.fogStrength;
        d.fog = f;
    }
    auto technique = parseTechnique(o.technique);
    if (!technique) throw RainParameterError("rain: --technique must be gs, instanced or points");
    d.technique = *technique;
    return d;
}

prism::image::Image8 shoot(const Options& o, const RainSceneDesc& desc) {
    RainScene scene(desc);
    for (int i = 0; i < o.warmup; ++i) scene.update(1.0f / 30.0f);
    return scene.render(o.width, o.height);
}

// --sequence N: N frames 1/30 s apart after the warm-up, each timed, and a one-row strip.
int writeSequence(const Options& o) {
    RainScene scene(sceneFor(o, std::max(o.view, 0), parseIntensity(o.intensity), o.wind, o.fog));
    for (int i = 0; i < o.warmup; ++i) scene.update(1.0f / 30.0f);
    std::vector<prism::image::Image8> frames;
    std::vector<std::string> labels;
    for (int i = 0; i < o.sequence; ++i) {
        if (i > 0) scene.update(1.0f / 30.0f);
        const auto t0 = std::chrono::steady_clock::now();
        frames.push_back(scene.render(o.width, o.height));
        char name[32];
        std::snprintf(name, sizeof name, "frame_%02d.png", i);
        prism::image::writePng(fs::path(o.out) / name, frames.back());
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        char label[48];
        std::snprintf(label, sizeof label, "t=%.3f s", static_cast<double>(o.warmup + i) / 30.0);
        labels.emplace_back(label);
        std::cout << "prism-rain: wrote " << (fs::path(o.out) / name).string() << " (" << s << " s)\n";
    }
    const fs::path strip = fs::path(o.out) / "sequence.png";
    prism::image::writePng(strip, prism::image::composeContactSheet(frames, labels, o.sequence));
    std::cout << "prism-rain: wrote " << strip.string() << "\n";
    return 0;
}

int writeImages(const Options& o) {
    auto context = prism::gl::createContext(prism::gl::ContextOptions{.majorVersion = 4, .minorVersion = 3});
    fs::create_directories(o.out);
    if (o.sequence > 0) return writeSequence(o);
    if (o.view >= 0) {
        const fs::path file = fs::path(o.out) / "rain.png";
        prism::image::writePng(file, shoot(o, sceneFor(o, o.view, parseIntensity(o.intensity), o.wind, o.fog)));
        std::cout << "prism-rain: wrote " << file.string() << "\n";
        return 0;
    }
    struct Shot {
        std::string name;
        int view;
        RainClass rain;
        float wind;
        bool fog;
    };
    const std::vector<Shot> shots = {
        {"view0-moderate", 0, RainClass::Moderate, 0.0f, false},
        {"view0-moderate-wind", 0, RainClass::Moderate, 7.0f, false},
        {"view1-heavy", 1, RainClass::Heavy, 0.0f, false},
        {"view1-heavy-wind", 1, RainClass::Heavy, 7.0f, false},
        {"view0-moderate-fog", 0, RainClass::Moderate, 0.0f, true},
        {"view2-cloudburst", 2, RainClass::Cloudburst, 2.0f, false},
    };
    std::vector<prism::image::Image8> images;
    std::vector<std::string> labels;
    for (const auto& s : shots) {
        const auto t0 = std::chrono::steady_clock::now();
        images.push_back(shoot(o, sceneFor(o, s.view, rainClassInfo(s.rain).intensity, s.wind, s.fog)));
        labels.push_back(s.name);
        const fs::path file = fs::path(o.out) / (s.name + ".png");
        prism::image::writePng(file, images.back());
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        std::cout << "prism-rain: wrote " << file.string() << " (" << ms << " ms)\n";
    }
    const fs::path sheet = fs::path(o.out) / "rain-sheet.png";
    prism::image::writePng(sheet, prism::image::composeContactSheet(images, labels, 3));
    std::cout << "prism-rain: wrote " << sheet.string() << "\n";
    return 0;
}

#if PRISM_RAIN_HAVE_GLFW
struct Live {
    Options options;
    int rainClass = 2;  // moderate
    float wind = 0.0f;
    float windDirection = 200.0f;
    bool fog = false;
    int technique = 0;
    float yaw = 0.0f;
    glm::vec3 eye{0.0f, 1.7f, 6.0f};
    bool rebuild = false;
    std::string message;
};

constexpr StreakTechnique kTechniques[] = {StreakTechnique::GeometryShader, StreakTechnique::Instanced,
                                           StreakTechnique::PointSprites};

void pressKey(Live& s, RainScene& scene, int key, bool shift) {
    const int classes = static_cast<int>(rainClasses().size());
    switch (key) {
        case GLFW_KEY_I: s.rainClass = std::min(s.rainClass + 1, classes - 1); break;
        case GLFW_KEY_K: s.rainClass = std::max(s.rainClass - 1, 0); break;
        case GLFW_KEY_W:
            if (shift)
                s.windDirection = std::fmod(s.windDirection + 45.0f, 360.0f);
            else
                s.wind = s.wind >= 12.0f ? 0.0f : s.wind + 2.0f;
            break;
        case GLFW_KEY_F:
            s.fog = !s.fog;
            s.rebuild = true;
            return;
        case GLFW_KEY_T:
            s.technique = (s.technique + 1) % 3;
            scene.setTechnique(kTechniques[s.technique]);
            return;
        default: return;
    }
    if (auto* rain = scene.rain()) {
        rain->setIntensity(rainClasses()[static_cast<std::size_t>(s.rainClass)].intensity);
        rain->setWind(WindParams{s.windDirection, s.wind});
    }
}

struct KeyContext {
    Live* live;
    RainScene** scene;
};

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    auto& k = *static_cast<KeyContext*>(glfwGetWindowUserPointer(window));
    if (key == GLFW_KEY_ESCAPE) {
        glfwSetWindowShouldClose(window, GLFW_TRUE);
        return;
    }
    if (key == GLFW_KEY_LEFT) k.live->yaw -= 0.08f;
    if (key == GLFW_KEY_RIGHT) k.live->yaw += 0.08f;
    const glm::vec3 forward(std::sin(k.live->yaw), 0.0f, -std::cos(k.live->yaw));
    if (key == GLFW_KEY_UP) k.live->eye += 0.5f * forward;
    if (key == GLFW_KEY_DOWN) k.live->eye -= 0.5f * forward;
    pressKey(*k.live, **k.scene, key, (mods & GLFW_MOD_SHIFT) != 0);
}

// The window's starting state: --intensity names the class, --technique the technique.
Live startingState(const Options& o) {
    Live live;
    live.options = o;
    live.wind = o.wind;
    live.windDirection = o.windDirection;
    live.fog = o.fog;
    if (const auto c = parseRainClass(o.intensity)) {
        for (std::size_t i = 0; i < rainClasses().size(); ++i)
            if (rainClasses()[i].intensity == rainClassInfo(*c).intensity) live.rainClass = static_cast<int>(i);
    } else {
        throw RainParameterError("rain: with --window, --intensity must name a class (drizzle..cloudburst)");
    }
    for (int i = 0; i < 3; ++i)
        if (parseTechnique(o.technique) == kTechniques[i]) live.technique = i;
    return live;
}

std::string windowTitle(const Live& live, RainScene& scene, double smoothedMs) {
    const auto* rain = scene.rain();
    return "Prism rain - " + std::string(rainClasses()[static_cast<std::size_t>(live.rainClass)].name) + ", " +
           std::to_string(rain ? rain->particleCount() : 0) + " drops, wind " +
           std::to_string(static_cast<int>(live.wind)) + " m/s, " + (live.fog ? "fog, " : "") +
           std::string(techniqueName(kTechniques[live.technique])) + ", " +
           std::to_string(static_cast<int>(smoothedMs)) + " ms";
}

int runWindow(const Options& o) {
    prism::gl::ContextOptions co{.majorVersion = 4, .minorVersion = 3};
    co.width = o.width;
    co.height = o.height;
    co.windowTitle = "Prism rain";
    co.vsync = o.frames == 0;
    auto context = prism::gl::createContext(prism::gl::Backend::Glfw, co);
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    Live live = startingState(o);
    auto build = [&] {
        RainSceneDesc d =
            sceneFor(o, 0, rainClasses()[static_cast<std::size_t>(live.rainClass)].intensity, live.wind, live.fog);
        d.technique = kTechniques[live.technique];
        return std::make_unique<RainScene>(d);
    };
    std::unique_ptr<RainScene> scene = build();
    RainScene* current = scene.get();
    KeyContext keys{&live, &current};
    glfwSetWindowUserPointer(window, &keys);
    glfwSetKeyCallback(window, onKey);

    auto last = std::chrono::steady_clock::now();
    double smoothedMs = 0.0;
    const int demo[] = {GLFW_KEY_I, GLFW_KEY_K, GLFW_KEY_W, GLFW_KEY_F, GLFW_KEY_T};
    for (long frame = 0; !context->shouldClose() && (o.frames == 0 || frame < o.frames); ++frame) {
        if (o.demoKeys && frame >= 1 && frame <= 5) pressKey(live, *current, demo[frame - 1], false);
        if (live.rebuild) {
            scene.reset();
            scene = build();
            current = scene.get();
            live.rebuild = false;
        }
        const auto now = std::chrono::steady_clock::now();
        const float dt = std::chrono::duration<float>(now - last).count();
        last = now;
        prism::view::Camera cam = current->camera();
        cam.eye = live.eye;
        cam.target = live.eye + glm::vec3(std::sin(live.yaw), 0.02f, -std::cos(live.yaw));
        current->setCamera(cam);
        current->update(frame == 0 ? 0.0f : dt);
        int w = 0, h = 0;
        glfwGetFramebufferSize(window, &w, &h);
        prism::gl::Framebuffer::bindDefault();
        current->draw(std::max(w, 1), std::max(h, 1));
        glFinish();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - now).count();
        smoothedMs = frame == 0 ? ms : 0.9 * smoothedMs + 0.1 * ms;
        const std::string title = windowTitle(live, *current, smoothedMs);
        glfwSetWindowTitle(window, title.c_str());
        context->swapBuffers();
        context->pollEvents();
    }
    std::cout << "prism-rain: " << rainClasses()[static_cast<std::size_t>(live.rainClass)].name << ", "
              << (current->rain() ? current->rain()->particleCount() : 0) << " particles, last frame " << smoothedMs
              << " ms (smoothed)\n";
    return 0;
}
#else
int runWindow(const Options&) {
    std::cerr << "prism-rain: this build has no GLFW (install libglfw3-dev); --window is unavailable\n";
    return 1;
}
#endif

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"prism-rain: a rain scene (camera-following particles, light-dependent streaks, fog)"};
    app.add_option("--out", o.out, "directory for the PNG images")->capture_default_str();
    app.add_option("--seed", o.seed, "random seed of the rain")->capture_default_str();
    app.add_option("--width", o.width, "image width")->capture_default_str()->check(CLI::Range(16, 4096));
    app.add_option("--height", o.height, "image height")->capture_default_str()->check(CLI::Range(16, 4096));
    app.add_option("--warmup", o.warmup, "simulation steps of 1/30 s before an image")
        ->capture_default_str()
        ->check(CLI::Range(0, 10000));
    app.add_option("--intensity", o.intensity, "rain class (drizzle..cloudburst) or cm/h, with --view")
        ->capture_default_str();
    app.add_option("--wind", o.wind, "wind strength in m/s, with --view or --window")->capture_default_str();
    app.add_option("--wind-direction", o.windDirection, "degrees in the xz plane (0 = +x)")->capture_default_str();
    app.add_flag("--fog", o.fog, "distance fog and fog billboards, with --view or --window");
    app.add_option("--fog-strength", o.fogStrength, "fog billboard strength 0..1")->capture_default_str();
    app.add_option("--technique", o.technique, "gs, instanced or points")->capture_default_str();
    app.add_option("--view", o.view, "render only this view (0, 1, 2) into rain.png")->check(CLI::Range(0, 2));
    app.add_flag("--window", o.window, "show the rain live in a GLFW window");
    app.add_option("--frames", o.frames, "with --window: quit after N frames (0 = run until Esc)");
    app.add_flag("--demo-keys", o.demoKeys, "with --window: press I, K, W, F, T once each (smoke test)");
    app.add_option("--sequence", o.sequence, "render N consecutive frames (1/30 s apart) and a strip")
        ->check(CLI::Range(1, 64));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    if (const std::string m = misplacedFlag(app, o); !m.empty()) {
        std::cerr << "prism-rain: error: " << m << "\n";
        return 2;
    }
    try {
        return o.window ? runWindow(o) : writeImages(o);
    } catch (const std::exception& e) {
        std::cerr << "prism-rain: error: " << e.what() << "\n";
        return 1;
    }
}
