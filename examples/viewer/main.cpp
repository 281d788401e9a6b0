// viewer: the interactive GLFW window over the catalogue and the example scenes, with
// Dear ImGui panels for every system (docs/viewer.md). Needs an X display; on a headless
// machine run it under `xvfb-run -a`. `viewer --help` lists the options.
//   Left/Right, Up/Down  rotate the mesh        S  next shader
//   M                    next mesh              +/-  subdivision level
//   Esc                  quit
// The console gets a line per change of the program in use ("viewer: program ..."), per
// reference readout ("viewer: reference ...") and per hot reload (--watch).
// SIGINT/SIGTERM end the loop cleanly (the screenshot is still written).
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "catalogue_view.hpp"
#include "error_overlay.hpp"
#include "gpu_timer.hpp"
#include "imgui_layer.hpp"
#include "panels/panels.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/gl/program.hpp"
#include "prism/image/png_io.hpp"
#include "prism/rain/rain_classes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"
#include "prism/shaders_sources.hpp"  // kSourceTree: where the catalogue was built from, for --watch
#include "reference_check.hpp"
#include "sampling_reference.hpp"
#include "scene_display.hpp"
#include "variant_choice.hpp"
#include "viewer_actions.hpp"
#include "viewer_input.hpp"
#include "viewer_options.hpp"
#include "viewer_script.hpp"

namespace {

using namespace prism::viewer;
const prism::catalog::Catalog& kCatalog = prism::shaders::kCatalog;
const prism::catalog::SourceTree& kSourceTree = prism::shaders::kSourceTree;

volatile std::sig_atomic_t gStopRequested = 0;
void onStopSignal(int) {
    gStopRequested = 1;
}

// The overlay shows the first outstanding error, its path relative to the watched tree.
std::string overlayText(const std::vector<std::string>& errors, const std::string& root) {
    if (errors.empty()) return {};
    std::string text = errors.front();
    for (std::size_t at; (at = text.find(root + "/")) != std::string::npos;) text.erase(at, root.size() + 1);
    if (errors.size() > 1) text += "(+" + std::to_string(errors.size() - 1) + " more errors: see the console)";
    return text;
}

prism::image::Image8 readBackBuffer(int width, int height) {
    prism::image::Image8 image(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.data.data());
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y)  // GL's row 0 is the bottom
        std::swap_ranges(image.data.begin() + static_cast<std::ptrdiff_t>(y * row),
                         image.data.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                         image.data.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
    for (std::size_t i = 3; i < image.data.size(); i += 4) image.data[i] = 255;  // the window is opaque
    return image;
}

std::vector<std::string> exampleScenes() {
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(PRISM_SOURCE_DIR "/examples/scenes", ec))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// Everything the command line names, checked before a window opens; throws with the reason.
void applyCommandLine(ViewerState& state, const ViewerOptions& args, std::optional<ViewerScript>& script) {
    selectShader(state, kCatalog, args.shader);
    for (const auto& v : args.variant) {
        const auto eq = v.find('=');
        pickAxis(state, v.substr(0, eq), v.substr(eq + 1));
    }
    const auto& c = state.catalogue;
    const std::string why = whyNotAVariant(*prism::catalog::findShader(kCatalog, c.shader),
                                           prism::render::featuresOf(c.lights, c.fog.has_value()), c.picks);
    if (!why.empty()) throw std::invalid_argument("--variant: " + why);
    setParameter(state, "mesh", args.mesh);
    setParameter(state, "subdivision", std::to_string(args.subdivision));
    if (std::find(std::begin(kMeshes), std::end(kMeshes), args.mesh) == std::end(kMeshes))
        throw std::invalid_argument("unknown mesh '" + args.mesh + "'");
    if (!args.scene.empty()) openScene(state, args.scene);
    if (!args.script.empty()) script = ViewerScript::load(args.script);
}

std::unique_ptr<prism::gl::Context> openWindow(const ViewerOptions& args, bool scripted) {
    prism::gl::ContextOptions options;
    options.width = args.width;
    options.height = args.height;
    options.majorVersion = 4;  // rain and the water step use compute shaders
    options.minorVersion = 3;
    options.windowTitle = "Prism viewer";
    options.vsync = args.frames == 0 && !scripted;
    return prism::gl::createContext(prism::gl::Backend::Glfw, options);
}

// The window's frame loop. Each frame is a fixed sequence of stages: hot reload, the next
// script event, the view (scene or catalogue), the readouts, the panels, the script's
// expectation, the screenshot, and the swap. A stage that must end the program returns its
// exit code.
class ViewerApp {
  public:
    ViewerApp(const ViewerOptions& args, ViewerState& state, std::optional<ViewerScript>& script)
        : args_(args),
          state_(state),
          script_(script),
          context_(openWindow(args, script.has_value())),
          window_(static_cast<GLFWwindow*>(context_->nativeWindow())),
          catalogueView_(cache_, kCatalog) {
        installKeyHandler(window_, state_, kCatalog);
        if (state_.panels) ui_.emplace(window_);  // after our key callback: ImGui chains to it
        if (args_.watch) {
            // The tree prism_add_shaders() recorded for the catalogue, or a copy of it (--source-root).
            const auto watchOptions = prism::render::ShaderWatchOptions::from(kSourceTree, args_.sourceRoot);
            watcher_ = std::make_unique<prism::render::ShaderWatcher>(cache_, watchOptions);
            std::cout << "viewer: watching " << watcher_->watchedFiles().size() << " files under "
                      << watcher_->sourceRoot() << std::endl;
        }
        std::cout << "viewer: frame time from " << (timer_.gpuTimed() ? "GL_TIME_ELAPSED queries" : "the CPU clock")
                  << std::endl;
    }

    int run() {
        const long maxFrames = args_.frames;
        for (long frame = 0;
             !context_->shouldClose() && !gStopRequested && (maxFrames == 0 || frame < maxFrames) && !scriptDone_;
             ++frame) {
            if (const auto exit = runFrame(frame)) return *exit;
        }
        if (!args_.screenshot.empty() && !screenshotWritten_) writeScreenshot();  // stopped between two frames
        std::cout << "viewer: last frame " << state_.readouts.frameMs << " ms ("
                  << (state_.readouts.gpuTimed ? "GPU" : "CPU") << "), " << cache_.size() << " programs cached, "
                  << reference_.referencesRendered() << " exact-sphere references rendered, "
                  << samplingReference_.referencesRendered() << " sampling references rendered\n";
        return 0;
    }

  private:
    std::optional<int> runFrame(long frame) {
        if (watcher_) pollHotReload();
        expected_.clear();
        if (script_ && !applyScriptEvent()) return 1;
        glfwGetFramebufferSize(window_, &w_, &h_);
        w_ = std::max(w_, 1), h_ = std::max(h_, 1);
        const int left = state_.panels ? std::min(static_cast<int>(kPanelWidth), w_ - 1) : 0;
        const int viewWidth = w_ - left;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, w_, h_);
        glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        timer_.begin();
        bool sceneRendered = false;
        const std::string program = drawView(left, viewWidth, sceneRendered);
        timer_.end();
        updateReadouts(frame, program, sceneRendered, viewWidth);
        if (ui_) {
            ui_->begin();
            drawControlPanels(state_, kCatalog, sceneFiles_, cache_.size());
            drawOverlay(state_, static_cast<float>(left));
            ui_->end();
        }
        overlay_.draw(w_, h_);
        if (!expected_.empty() && state_.readouts.program.find(expected_) == std::string::npos) {
            std::cerr << script_->path() << ":" << expectLine_ << ":1: error: the program in use is '"
                      << state_.readouts.program << "', not '" << expected_ << "'\n";
            return 1;
        }
        const bool lastFrame = gStopRequested || scriptDone_ || (args_.frames > 0 && frame + 1 == args_.frames);
        if (!args_.screenshot.empty() && lastFrame && !screenshotWritten_) writeScreenshot();
        const std::string title = "Prism viewer - " + state_.readouts.program;
        glfwSetWindowTitle(window_, title.c_str());
        context_->swapBuffers();
        context_->pollEvents();
        return std::nullopt;
    }

    void pollHotReload() {
        const auto result = watcher_->poll();
        for (const auto& f : result.changedFiles) std::cout << "viewer: changed " << f << "\n";
        for (const auto& r : result.reloaded) std::cout << "viewer: reloaded " << r << "\n";
        for (const auto& d : result.diagnostics) std::cerr << d;
        if (result.checked) {
            const auto text = overlayText(watcher_->errors(), watcher_->sourceRoot());
            if (text != overlay_.text())
                std::cout << "viewer: overlay " << (text.empty() ? "cleared" : "shows: " + text) << std::endl;
            overlay_.setText(text);
        }
        std::cerr.flush();
    }

    // False after an event that fails (reported as path:line:1: error: ...).
    bool applyScriptEvent() {
        const bool wasLast = script_->finished();
        if (const auto event = script_->next()) {
            try {
                expected_ = applyEvent(state_, kCatalog, window_, *script_, *event);
                expectLine_ = event->line;
            } catch (const std::exception& e) {
                std::cerr << script_->path() << ":" << event->line << ":1: error: " << e.what() << "\n";
                return false;
            }
        }
        scriptDone_ = wasLast && args_.frames == 0;  // one frame after the last event
        return true;
    }

    // The open scene, or the catalogue view; returns the program label of what was drawn.
    std::string drawView(int left, int viewWidth, bool& sceneRendered) {
        if (!state_.scene.open) return catalogueView_.draw(state_, left, viewWidth, h_);
        const std::string errorBefore = sceneDisplay_.error();
        sceneRendered = sceneDisplay_.draw(state_.scene, left, viewWidth, h_);
        if (sceneDisplay_.error() != errorBefore) {
            if (!sceneDisplay_.error().empty())
                std::cerr << "viewer: error: " << state_.scene.file << ": " << sceneDisplay_.error() << std::endl;
            panelError() = sceneDisplay_.error();
        }
        if (!sceneRendered) return state_.readouts.program;
        state_.readouts.sceneRenderMs = sceneDisplay_.lastRenderMs();
        const auto& rain = state_.scene.scene.rain;
        std::cout << "viewer: scene " << state_.scene.file << " rendered in "
                  << static_cast<long>(state_.readouts.sceneRenderMs) << " ms"
                  << (rain ? ", rain " + std::string(prism::rain::rainClassInfo(rain->intensityClass).name) : "")
                  << std::endl;
        return sceneDisplay_.programLabel(state_.scene);
    }

    // Frame time, the program in use, and the reference readouts of the current view.
    void updateReadouts(long frame, const std::string& program, bool sceneRendered, int viewWidth) {
        state_.readouts.frameMs = timer_.lastMs();
        state_.readouts.gpuTimed = timer_.gpuTimed();
        const bool programChanged = program != state_.readouts.program;
        if (programChanged) std::cout << "viewer: program " << program << std::endl;
        state_.readouts.program = program;
        const std::string viewKey = state_.scene.open ? state_.scene.file : std::string();
        if (viewKey != lastViewKey_) {  // a readout belongs to the view it was measured in
            state_.readouts.referenceText.clear();
            referenceSignature_.clear();
            lastViewKey_ = viewKey;
        }
        const bool sampling = state_.scene.open && state_.scene.scene.stochastic.has_value();
        if (state_.readouts.referenceOn && sampling &&
            (programChanged || sceneRendered || state_.readouts.referenceText.empty()))
            setReferenceText(samplingReference_.measure(*state_.scene.scene.stochastic));
        if (!state_.readouts.referenceOn) state_.readouts.referenceText.clear();
        if (state_.readouts.referenceOn && !state_.scene.open) measureCatalogueReference(frame, program, viewWidth);
    }

    // The exact-sphere error of the catalogue view: again when the view changed, and every 30 frames.
    void measureCatalogueReference(long frame, const std::string& program, int viewWidth) {
        const auto job = catalogueView_.job(state_, viewWidth, h_);
        const std::string why = referenceUnavailable(job, state_.catalogue.mesh, job.variant);
        const auto& c = state_.catalogue;
        const std::string signature = program + c.mesh + std::to_string(c.subdivision) +
                                      std::to_string(c.yaw + 7 * c.pitch) + why + std::to_string(c.material.shininess) +
                                      std::to_string(c.material.specular);
        if (signature != referenceSignature_ || frame % 30 == 0) {
            setReferenceText(why.empty() ? reference_.measure(cache_, job, catalogueView_.mesh()) : why);
            referenceSignature_ = signature;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, w_, h_);
    }

    void setReferenceText(const std::string& text) {
        if (text != state_.readouts.referenceText) std::cout << "viewer: reference " << text << std::endl;
        state_.readouts.referenceText = text;
    }

    void writeScreenshot() {
        prism::image::writePng(args_.screenshot, readBackBuffer(w_, h_));
        std::cout << "viewer: wrote " << args_.screenshot << std::endl;
        screenshotWritten_ = true;
    }

    const ViewerOptions& args_;
    ViewerState& state_;
    std::optional<ViewerScript>& script_;
    std::unique_ptr<prism::gl::Context> context_;
    GLFWwindow* window_;
    std::optional<ImGuiLayer> ui_;
    prism::render::ProgramCache cache_{kCatalog};
    CatalogueRenderer catalogueView_;
    SceneDisplay sceneDisplay_{kCatalog};
    ReferenceCheck reference_;
    SamplingReference samplingReference_;
    FrameTimer timer_;
    const std::vector<std::string> sceneFiles_ = exampleScenes();
    std::unique_ptr<prism::render::ShaderWatcher> watcher_;
    ErrorOverlay overlay_;
    bool screenshotWritten_ = false;
    bool scriptDone_ = false;
    std::string referenceSignature_, lastViewKey_ = "(none)";
    std::string expected_;  // this frame's script expectation: text the program in use must contain
    int expectLine_ = 0;
    int w_ = 0, h_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
    int exitCode = 0;
    const auto args = parseViewerOptions(argc, argv, exitCode);
    if (!args) return exitCode;
    ViewerState state;
    state.panels = args->panels;
    std::optional<ViewerScript> script;
    try {
        applyCommandLine(state, *args, script);
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 2;
    }
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    prism::gl::setDefaultUnsetUniformCheck(true);  // a forgotten uniform is reported where it would show
    try {
        ViewerApp app(*args, state, script);
        return app.run();
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 1;
    }
}
