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
#include "prism/image/png_io.hpp"
#include "prism/rain/rain_classes.hpp"
#include "prism/render/shader_watcher.hpp"
#include "prism/shaders.hpp"
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

}  // namespace

int main(int argc, char** argv) {
    int exitCode = 0;
    const auto args = parseViewerOptions(argc, argv, exitCode);
    if (!args) return exitCode;
    const long maxFrames = args->frames;
    ViewerState state;
    state.panels = args->panels;
    std::optional<ViewerScript> script;
    try {  // everything the command line names is checked before a window opens
        selectShader(state, kCatalog, args->shader);
        for (const auto& v : args->variant) {
            const auto eq = v.find('=');
            pickAxis(state, v.substr(0, eq), v.substr(eq + 1));
        }
        const auto& c = state.catalogue;
        const std::string why = whyNotAVariant(*prism::catalog::findShader(kCatalog, c.shader),
                                               prism::render::featuresOf(c.lights, c.fog.has_value()), c.picks);
        if (!why.empty()) throw std::invalid_argument("--variant: " + why);
        setParameter(state, "mesh", args->mesh);
        setParameter(state, "subdivision", std::to_string(args->subdivision));
        if (std::find(std::begin(kMeshes), std::end(kMeshes), args->mesh) == std::end(kMeshes))
            throw std::invalid_argument("unknown mesh '" + args->mesh + "'");
        if (!args->scene.empty()) openScene(state, args->scene);
        if (!args->script.empty()) script = ViewerScript::load(args->script);
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 2;
    }
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
    try {
        prism::gl::ContextOptions options;
        options.width = args->width;
        options.height = args->height;
        options.majorVersion = 4;  // rain and the water step use compute shaders
        options.minorVersion = 3;
        options.windowTitle = "Prism viewer";
        options.vsync = maxFrames == 0 && !script;
        auto context = prism::gl::createContext(prism::gl::Backend::Glfw, options);
        auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
        installKeyHandler(window, state, kCatalog);
        std::optional<ImGuiLayer> ui;
        if (state.panels) ui.emplace(window);  // after our key callback: ImGui chains to it

        prism::render::ProgramCache cache(kCatalog);
        CatalogueRenderer catalogueView(cache, kCatalog);
        SceneDisplay sceneDisplay(kCatalog);
        ReferenceCheck reference;
        SamplingReference samplingReference;
        FrameTimer timer;
        const std::vector<std::string> sceneFiles = exampleScenes();
        std::unique_ptr<prism::render::ShaderWatcher> watcher;
        ErrorOverlay overlay;
        if (args->watch) {
            prism::render::ShaderWatchOptions watchOptions;
            watchOptions.sourceRoot = args->sourceRoot;
            watcher = std::make_unique<prism::render::ShaderWatcher>(cache, watchOptions);
            std::cout << "viewer: watching " << watcher->watchedFiles().size() << " files under "
                      << args->sourceRoot << std::endl;
        }
        std::cout << "viewer: frame time from " << (timer.gpuTimed() ? "GL_TIME_ELAPSED queries" : "the CPU clock")
                  << std::endl;
        bool screenshotWritten = false;
        std::string referenceSignature, lastViewKey = "(none)";
        int w = 0, h = 0;
        auto writeScreenshot = [&]() {
            prism::image::writePng(args->screenshot, readBackBuffer(w, h));
            std::cout << "viewer: wrote " << args->screenshot << std::endl;
            screenshotWritten = true;
        };
        bool scriptDone = false;
        for (long frame = 0; !context->shouldClose() && !gStopRequested && (maxFrames == 0 || frame < maxFrames) &&
                             !scriptDone;
             ++frame) {
            if (watcher) {
                const auto result = watcher->poll();
                for (const auto& f : result.changedFiles) std::cout << "viewer: changed " << f << "\n";
                for (const auto& r : result.reloaded) std::cout << "viewer: reloaded " << r << "\n";
                for (const auto& d : result.diagnostics) std::cerr << d;
                if (result.checked) {
                    const auto text = overlayText(watcher->errors(), watcher->sourceRoot());
                    if (text != overlay.text())
                        std::cout << "viewer: overlay " << (text.empty() ? "cleared" : "shows: " + text) << std::endl;
                    overlay.setText(text);
                }
                std::cerr.flush();
            }
            std::string expected;
            int expectLine = 0;
            if (script) {
                const bool wasLast = script->finished();
                if (const auto event = script->next()) {
                    try {
                        expected = applyEvent(state, kCatalog, window, *script, *event);
                        expectLine = event->line;
                    } catch (const std::exception& e) {
                        std::cerr << script->path() << ":" << event->line << ":1: error: " << e.what() << "\n";
                        return 1;
                    }
                }
                scriptDone = wasLast && maxFrames == 0;  // one frame after the last event
            }
            glfwGetFramebufferSize(window, &w, &h);
            w = std::max(w, 1), h = std::max(h, 1);
            const int left = state.panels ? std::min(static_cast<int>(kPanelWidth), w - 1) : 0;
            const int viewWidth = w - left;
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, w, h);
            glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            timer.begin();
            std::string program;
            bool sceneRendered = false;
            if (state.scene.open) {
                const std::string errorBefore = sceneDisplay.error();
                sceneRendered = sceneDisplay.draw(state.scene, left, viewWidth, h);
                if (sceneDisplay.error() != errorBefore) {
                    if (!sceneDisplay.error().empty())
                        std::cerr << "viewer: error: " << state.scene.file << ": " << sceneDisplay.error() << std::endl;
                    panelError() = sceneDisplay.error();
                }
                if (sceneRendered) {
                    program = sceneDisplay.programLabel(state.scene);
                    state.readouts.sceneRenderMs = sceneDisplay.lastRenderMs();
                    std::cout << "viewer: scene " << state.scene.file << " rendered in "
                              << static_cast<long>(state.readouts.sceneRenderMs) << " ms"
                              << (state.scene.scene.rain
                                      ? ", rain " + std::string(prism::rain::rainClassInfo(
                                                        state.scene.scene.rain->intensityClass).name)
                                      : "")
                              << std::endl;
                } else {
                    program = state.readouts.program;
                }
            } else {
                program = catalogueView.draw(state, left, viewWidth, h);
            }
            timer.end();
            state.readouts.frameMs = timer.lastMs();
            state.readouts.gpuTimed = timer.gpuTimed();
            const bool programChanged = program != state.readouts.program;
            if (programChanged) std::cout << "viewer: program " << program << std::endl;
            state.readouts.program = program;
            const std::string viewKey = state.scene.open ? state.scene.file : std::string();
            if (viewKey != lastViewKey) {  // a readout belongs to the view it was measured in
                state.readouts.referenceText.clear();
                referenceSignature.clear();
                lastViewKey = viewKey;
            }

            const bool sampling = state.scene.open && state.scene.scene.stochastic.has_value();
            if (state.readouts.referenceOn && sampling && (programChanged || sceneRendered || state.readouts.referenceText.empty())) {
                const std::string text = samplingReference.measure(*state.scene.scene.stochastic);
                if (text != state.readouts.referenceText) std::cout << "viewer: reference " << text << std::endl;
                state.readouts.referenceText = text;
            }
            if (!state.readouts.referenceOn) state.readouts.referenceText.clear();
            if (state.readouts.referenceOn && !state.scene.open) {
                const auto job = catalogueView.job(state, viewWidth, h);
                std::string why = referenceUnavailable(job, state.catalogue.mesh, job.variant);
                const std::string signature = program + state.catalogue.mesh +
                                              std::to_string(state.catalogue.subdivision) +
                                              std::to_string(state.catalogue.yaw + 7 * state.catalogue.pitch) + why +
                                              std::to_string(state.catalogue.material.shininess) +
                                              std::to_string(state.catalogue.material.specular);
                if (signature != referenceSignature || frame % 30 == 0) {
                    const std::string text = why.empty() ? reference.measure(cache, job, catalogueView.mesh()) : why;
                    if (text != state.readouts.referenceText) std::cout << "viewer: reference " << text << std::endl;
                    state.readouts.referenceText = text;
                    referenceSignature = signature;
                }
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                glViewport(0, 0, w, h);
            }

            if (ui) {
                ui->begin();
                drawControlPanels(state, kCatalog, sceneFiles, cache.size());
                drawOverlay(state, static_cast<float>(left));
                ui->end();
            }
            overlay.draw(w, h);
            if (!expected.empty() && state.readouts.program.find(expected) == std::string::npos) {
                std::cerr << script->path() << ":" << expectLine << ":1: error: the program in use is '"
                          << state.readouts.program << "', not '" << expected << "'\n";
                return 1;
            }
            const bool lastFrame = gStopRequested || scriptDone || (maxFrames > 0 && frame + 1 == maxFrames);
            if (!args->screenshot.empty() && lastFrame && !screenshotWritten) writeScreenshot();
            const std::string title = "Prism viewer - " + state.readouts.program;
            glfwSetWindowTitle(window, title.c_str());
            context->swapBuffers();
            context->pollEvents();
        }
        if (!args->screenshot.empty() && !screenshotWritten) writeScreenshot();  // stopped between two frames
        std::cout << "viewer: last frame " << state.readouts.frameMs << " ms ("
                  << (state.readouts.gpuTimed ? "GPU" : "CPU") << "), " << cache.size() << " programs cached, "
                  << reference.referencesRendered() << " exact-sphere references rendered, "
                  << samplingReference.referencesRendered() << " sampling references rendered\n";
    } catch (const std::exception& e) {
        std::cerr << "viewer: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
