// prism-render: renders one catalogue shader on one mesh, or a JSON scene
// (--scene FILE.json, docs/scenes.md), into a PNG, headlessly.
//   prism-render --shader phong --mesh torus --subdiv 3 --shininess 64
//                --light-dir -1,-1,-1 --size 512x512 --out phong.png [--backend egl, osmesa or vulkan]
//   prism-render --scene examples/scenes/soft_shadows.json --spp 1 --sampler sorted --frames 8 --out s.png
// --spp, --sampler, --frame and --frames override the scene's "stochastic" settings (a
// usage error for a scene without them): --frame K renders frame K of the sequence,
// --frames K the mean of frames 0..K-1.
// With --scene, --size WxH overrides the scene's "image" size; the flags that only
// describe a catalogue render (--mesh, --subdiv, --variant, --shininess, --specular,
// --color, --light-dir, --scale) are usage errors, as is a GL --backend for a "stochastic"
// scene, drawn on the CPU or through --backend vulkan: no flag is silently ignored.
// --check-finite renders to RGBA32F and exits 3, printing the count, if any pixel is
// NaN or Inf. Bad input exits 2 with a message and writes no image.
// --backend vulkan (or PRISM_GL_BACKEND=vulkan without --backend) draws the catalogue's
// SPIR-V through prism::vk (docs/vulkan.md), also a "stochastic" scene's soft shadows; a scene
// with a system that has no Vulkan path exits 2 naming it.
#include <CLI/CLI.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <iostream>
#include <optional>

#include "prism/apps/cli_parsing.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/geometry/obj_loader.hpp"
#include "prism/render/offscreen_render.hpp"
#include "prism/image/png_io.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/scene_renderer.hpp"
#include "prism/scene/stochastic.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/render/vulkan_render.hpp"
#include "prism/scene/vulkan_scene.hpp"
#include "prism/shaders.hpp"

namespace {

constexpr int kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitNonFinite = 3;

struct Arguments {
    std::string shader, scene, mesh = "sphere", out, backend, lightDir = "-0.5,-0.6,-0.65", size = "512x512";
    std::string color = "0.8,0.35,0.25", scale = "1,1,1", shininess = "32", specular = "0.5";
    std::vector<std::string> variants;
    unsigned subdiv = 3;
    bool checkFinite = false;
    // Overrides of the scene's "stochastic" settings; nullopt: not given.
    std::optional<int> spp, frame, frames;
    std::optional<std::string> sampler;
    std::vector<std::string> shaderOnlyGiven;  // catalogue-render flags given (refused with --scene)
    bool sizeGiven = false, subdivGiven = false;
    bool stochasticGiven() const { return spp || frame || frames || sampler; }
    std::string stochasticFlags() const {
        std::string f;
        for (const auto& [given, name] :
             {std::pair{spp.has_value(), "--spp"}, std::pair{sampler.has_value(), "--sampler"},
              std::pair{frame.has_value(), "--frame"}, std::pair{frames.has_value(), "--frames"}})
            if (given) f += (f.empty() ? "" : ", ") + std::string(name);
        return f;
    }
};

int badInput(const std::string& message) {
    std::cerr << "prism-render: error: " << message << "\n";
    return kExitBadInput;
}

// --backend, else PRISM_GL_BACKEND (createContext's own choice), else nullopt: EGL, then OSMesa.
std::optional<prism::gl::Backend> backendOf(const Arguments& a, bool& ok) {
    ok = true;
    if (a.backend.empty()) {
        try {
            return prism::gl::backendFromEnvironment();
        } catch (const prism::gl::ContextError&) {
            return std::nullopt;  // createContext() reports the bad value as it always has
        }
    }
    auto backend = prism::gl::parseBackend(a.backend);
    ok = backend && *backend != prism::gl::Backend::Glfw;
    return backend;
}

constexpr const char* kBackends = "expected egl, osmesa or vulkan";

bool isVulkan(std::optional<prism::gl::Backend> backend) {
    return backend == prism::gl::Backend::Vulkan;
}

// Each stage below returns the exit code when the program must stop, nullopt to go on.
using Stop = std::optional<int>;

// The flags a scene render refuses or needs, before the file is read.
Stop checkSceneFlags(const Arguments& a) {
    if (a.out.empty()) return badInput("give --out FILE.png");
    if (a.checkFinite) return badInput("--check-finite works with --shader, not with --scene");
    if (!a.shaderOnlyGiven.empty())
        return badInput(a.shaderOnlyGiven.front() +
                        " describes a --shader render; a --scene file sets its own (docs/scenes.md)");
    if (a.sizeGiven && !prism::apps::parseSize(a.size))
        return badInput("--size " + a.size + ": expected WxH with 1 <= W, H <= 16384, e.g. 512x512");
    return std::nullopt;
}

// The scene file with the command line's size; meshes are checked before any GL work.
Stop loadScene(const Arguments& a, prism::scene::Scene& scene) {
    const auto size = prism::apps::parseSize(a.size);
    try {
        scene = prism::scene::loadScene(a.scene);
        for (const auto& o : scene.objects) (void)prism::render::namedMesh(o.mesh, 0);
    } catch (const std::exception& e) {
        return badInput(e.what());
    }
    if (a.sizeGiven) {  // the command line wins over the scene's "image" size
        scene.width = size->first;
        scene.height = size->second;
    }
    return std::nullopt;
}

// --spp, --sampler, --frame and --frames over the scene's "stochastic" settings, never silently ignored.
Stop applyStochasticFlags(const Arguments& a, prism::scene::Scene& scene) {
    if (!a.stochasticGiven()) return std::nullopt;
    if (!scene.stochastic)
        return badInput(a.stochasticFlags() + ": " + a.scene +
                        " has no \"stochastic\" effect (docs/scenes.md); these flags need one");
    auto& st = *scene.stochastic;
    if (a.sampler) {
        const auto kind = prism::scene::parseStochasticSampler(*a.sampler);
        if (!kind) return badInput("--sampler " + *a.sampler + ": expected white, bluenoise or sorted");
        st.sampler = *kind;
    }
    if (a.spp) st.spp = *a.spp;
    if (a.frame) {  // one frame: the scene's accumulation no longer applies
        st.frame = *a.frame;
        st.frames = 1;
    }
    if (a.frames) {  // the mean from frame 0
        st.frames = *a.frames;
        st.frame = 0;
    }
    if (st.sampler == prism::bluenoise::SamplerKind::Sorted &&
        st.frame > static_cast<int>(prism::scene::kMaxSortedFrame))
        return badInput("--frame " + std::to_string(st.frame) +
                        ": the sorted sampler replays every frame before K; use K <= " +
                        std::to_string(prism::scene::kMaxSortedFrame));
    return std::nullopt;
}

// A "stochastic" scene: on the CPU, no GL context; or each frame through Vulkan.
int writeStochasticScene(const Arguments& a, const prism::scene::Scene& scene,
                         std::optional<prism::gl::Backend> backend) {
    if (!a.backend.empty() && !isVulkan(backend))
        return badInput("--backend: " + a.scene +
                        " is drawn on the CPU (a \"stochastic\" scene), or through --backend vulkan; it uses no GL "
                        "backend");
    try {
        const auto& st = *scene.stochastic;
        if (isVulkan(backend)) {
            const prism::vk::Device device;
            prism::image::writePng(a.out, prism::scene::renderStochasticVulkan(st, scene.width, scene.height, device));
        } else {
            prism::image::writePng(a.out, prism::scene::renderStochastic(st, scene.width, scene.height));
        }
        std::cout << "prism-render: wrote " << a.out << " (soft shadows"
                  << (isVulkan(backend) ? " through vulkan, " : ", ") << prism::scene::stochasticSamplerName(st.sampler)
                  << ", " << st.spp << " spp, "
                  << (st.frames > 1 ? "mean of frames 0.." + std::to_string(st.frames - 1)
                                    : "frame " + std::to_string(st.frame))
                  << ")\n";
    } catch (const std::invalid_argument& e) {
        return badInput(e.what());
    } catch (const std::exception& e) {
        std::cerr << "prism-render: error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

// Runs a Vulkan draw: bad input (a bad name or variant, a scene system without a Vulkan
// path) exits 2, any other failure (no Vulkan driver) 1.
template <class Draw>
int guardedVulkan(const Draw& draw) {
    try {
        draw();
    } catch (const std::invalid_argument& e) {  // also UnknownShaderError
        return badInput(e.what());
    } catch (const prism::scene::SceneError& e) {
        return badInput(e.what());
    } catch (const std::exception& e) {
        std::cerr << "prism-render: error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

// A scene through Vulkan; a system without a Vulkan path is bad input.
int drawSceneVulkan(const Arguments& a, const prism::scene::Scene& scene) {
    return guardedVulkan([&] {
        const prism::render::VulkanFrame frame = prism::scene::vulkanFrameOf(scene);
        prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
        prism::image::writePng(a.out, vulkan.render(frame));
        std::cout << "prism-render: wrote " << a.out << " (vulkan on " << vulkan.device().name() << ", "
                  << frame.draws.size() << " draws, " << vulkan.pipelineCount() << " pipelines)\n";
    });
}

int drawScene(const Arguments& a, const prism::scene::Scene& scene, std::optional<prism::gl::Backend> backend) {
    if (isVulkan(backend)) return drawSceneVulkan(a, scene);
    try {
        auto context = backend ? prism::gl::createContext(*backend) : prism::gl::createContext();
        prism::scene::SceneRenderer renderer(prism::shaders::kCatalog);
        auto image = renderer.render(scene);
        prism::image::writePng(a.out, image);
        for (const auto& v : renderer.lastFrame().variants) std::cout << "draw: " << v << "\n";
        std::cout << "prism-render: wrote " << a.out << " (" << renderer.lastFrame().draws << " draws, "
                  << renderer.programs().size() + renderer.diffractionProgramsBuilt() << " programs)\n";
    } catch (const std::invalid_argument& e) {
        return badInput(e.what());
    } catch (const prism::scene::SceneError& e) {  // e.g. a diffraction material needing N > 200
        return badInput(e.what());
    } catch (const std::exception& e) {
        std::cerr << "prism-render: error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

int renderScene(const Arguments& a) {
    if (const Stop stop = checkSceneFlags(a)) return *stop;
    bool backendOk = true;
    auto backend = backendOf(a, backendOk);
    if (!backendOk) return badInput("--backend " + a.backend + ": " + kBackends);
    prism::scene::Scene scene;
    if (const Stop stop = loadScene(a, scene)) return *stop;
    if (const Stop stop = applyStochasticFlags(a, scene)) return *stop;
    if (scene.stochastic) return writeStochasticScene(a, scene, backend);
    return drawScene(a, scene, backend);
}

// The command line; Stop holds the exit code after --help or a usage error.
Stop parseArguments(int argc, char** argv, Arguments& a) {
    CLI::App app{"prism-render: render one catalogue shader on one mesh into a PNG"};
    auto* shaderOption = app.add_option("--shader", a.shader, "catalogue shader name");
    auto* sceneOption = app.add_option("--scene", a.scene, "render a JSON scene file instead (docs/scenes.md)");
    shaderOption->excludes(sceneOption);
    sceneOption->excludes(shaderOption);
    app.add_option("--variant", a.variants, "variant axis value NAME=VALUE (repeatable)")->allow_extra_args(false);
    app.add_option("--mesh", a.mesh, "sphere|icosphere|torus|cube|trefoil|grid|FILE.obj")->capture_default_str();
    app.add_option("--subdiv", a.subdiv, "subdivision level 0..7")->capture_default_str()->check(CLI::Range(0, 7));
    app.add_option("--shininess", a.shininess, "Phong exponent >= 0")->capture_default_str();
    app.add_option("--specular", a.specular, "specular strength >= 0")->capture_default_str();
    app.add_option("--color", a.color, "material colour r,g,b")->capture_default_str();
    app.add_option("--light-dir", a.lightDir, "key light direction x,y,z (world space)")->capture_default_str();
    app.add_option("--scale", a.scale, "world scale x,y,z")->capture_default_str();
    app.add_option("--size", a.size, "image size WxH")->capture_default_str();
    app.add_option("--out", a.out, "output PNG");
    app.add_option("--backend", a.backend, "egl|osmesa|vulkan (default: PRISM_GL_BACKEND, else egl, else osmesa)");
    using prism::scene::kMaxStochasticFrame, prism::scene::kMaxStochasticFrames, prism::scene::kMaxStochasticSpp;
    app.add_option("--spp", a.spp, "with --scene: samples per pixel of its stochastic effect")
        ->check(CLI::Range(1, static_cast<int>(kMaxStochasticSpp)));
    app.add_option("--sampler", a.sampler, "with --scene: white|bluenoise|sorted for its stochastic effect");
    auto* frameOption = app.add_option("--frame", a.frame, "with --scene: render frame K of the stochastic sequence")
                            ->check(CLI::Range(0, static_cast<int>(kMaxStochasticFrame)));
    auto* framesOption = app.add_option("--frames", a.frames, "with --scene: the mean of frames 0..K-1")
                             ->check(CLI::Range(1, static_cast<int>(kMaxStochasticFrames)));
    frameOption->excludes(framesOption);
    framesOption->excludes(frameOption);
    app.add_flag("--check-finite", a.checkFinite, "render RGBA32F; exit 3 if any pixel is NaN or Inf");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    }
    for (const char* flag :
         {"--mesh", "--subdiv", "--variant", "--shininess", "--specular", "--color", "--light-dir", "--scale"})
        if (app.count(flag) > 0) a.shaderOnlyGiven.emplace_back(flag);
    a.sizeGiven = app.count("--size") > 0;
    a.subdivGiven = app.count("--subdiv") > 0;
    return std::nullopt;
}

// The shader, its variant picks and the flags' numbers, checked before touching GL, so bad
// input writes nothing.
Stop catalogueJob(const Arguments& a, prism::render::RenderJob& job) {
    job.shader = a.shader;
    if (!prism::catalog::findShader(prism::shaders::kCatalog, a.shader)) {
        std::string known;
        for (const auto& s : prism::shaders::kCatalog.shaders)
            known += (known.empty() ? "" : ", ") + std::string(s.name);
        return badInput("unknown shader '" + a.shader + "'; known shaders: " + known);
    }
    for (const auto& v : a.variants) {
        auto eq = v.find('=');
        if (eq == std::string::npos || eq == 0) return badInput("--variant " + v + ": expected NAME=VALUE");
        job.variant.emplace_back(v.substr(0, eq), v.substr(eq + 1));
    }
    auto shininess = prism::apps::parseFiniteFloat(a.shininess);
    auto specular = prism::apps::parseFiniteFloat(a.specular);
    auto color = prism::apps::parseVec3(a.color);
    auto light = prism::apps::parseVec3(a.lightDir);
    auto scale = prism::apps::parseVec3(a.scale);
    auto size = prism::apps::parseSize(a.size);
    if (!shininess || *shininess < 0) return badInput("--shininess " + a.shininess + ": expected a finite number >= 0");
    if (!specular || *specular < 0) return badInput("--specular " + a.specular + ": expected a finite number >= 0");
    if (!color) return badInput("--color " + a.color + ": expected three finite numbers r,g,b");
    if (!light) return badInput("--light-dir " + a.lightDir + ": expected three finite numbers x,y,z");
    if (!scale) return badInput("--scale " + a.scale + ": expected three finite numbers x,y,z");
    if (!size) return badInput("--size " + a.size + ": expected WxH with 1 <= W, H <= 16384, e.g. 512x512");
    if (a.out.empty() && !a.checkFinite) return badInput("give --out FILE.png (or --check-finite)");
    if (a.subdivGiven && a.mesh != "sphere" && a.mesh != "icosphere" && a.mesh != "torus" && a.mesh != "grid")
        return badInput("--subdiv: mesh " + a.mesh +
                        " has no subdivision levels (sphere, icosphere, torus and grid have)");
    job.material.shininess = *shininess;
    job.material.specular = *specular;
    job.material.color = glm::vec4(*color, 1.0f);
    job.lights.directional.at(0).direction = *light;
    job.world = glm::scale(glm::mat4(1.0f), *scale);
    job.width = size->first;
    job.height = size->second;
    return std::nullopt;
}

// The catalogue render through Vulkan, from the catalogue's SPIR-V.
int drawCatalogueVulkan(const Arguments& a, const prism::render::RenderJob& job) {
    if (a.checkFinite) return badInput("--check-finite renders RGBA32F through GL; use --backend egl or osmesa");
    return guardedVulkan([&] {
        prism::render::VulkanRenderer vulkan(prism::shaders::kCatalog);
        prism::image::writePng(a.out, vulkan.render(job));
        std::cout << "prism-render: wrote " << a.out << " (vulkan on " << vulkan.device().name() << ")\n";
    });
}

// The catalogue render: RGBA8, or RGBA32F checked for NaN and Inf with --check-finite.
int drawCatalogue(const Arguments& a, const prism::render::RenderJob& job, std::optional<prism::gl::Backend> backend) {
    if (isVulkan(backend)) return drawCatalogueVulkan(a, job);
    try {
        auto context = backend ? prism::gl::createContext(*backend) : prism::gl::createContext();
        prism::render::ProgramCache cache(prism::shaders::kCatalog);
        cache.variantOf(job.shader, job.variant);  // throws UnknownShaderError for a bad variant
        if (a.checkFinite) {
            auto hdr = prism::render::renderImageF(cache, job);
            auto bad = prism::image::countNonFinite(hdr);
            if (bad > 0) {
                std::cerr << "prism-render: " << bad << " of " << hdr.pixelCount() << " pixels are NaN or Inf\n";
                return kExitNonFinite;
            }
            std::cout << "prism-render: all " << hdr.pixelCount() << " pixels finite\n";
            if (a.out.empty()) return kExitOk;
            prism::image::writePng(a.out, prism::image::toImage8(hdr));
        } else {
            prism::image::writePng(a.out, prism::render::renderImage8(cache, job));
        }
        std::cout << "prism-render: wrote " << a.out << "\n";
    } catch (const std::invalid_argument& e) {  // also UnknownShaderError: a bad name or variant
        return badInput(e.what());
    } catch (const std::exception& e) {
        std::cerr << "prism-render: error: " << e.what() << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

int renderCatalogue(const Arguments& a) {
    prism::render::RenderJob job;
    if (const Stop stop = catalogueJob(a, job)) return *stop;
    bool backendOk = true;
    const auto backend = backendOf(a, backendOk);
    if (!backendOk) return badInput("--backend " + a.backend + ": " + kBackends);
    try {
        job.mesh = prism::render::meshForShader(a.shader, prism::render::namedMesh(a.mesh, a.subdiv));
    } catch (const prism::geometry::ObjLoadError& e) {
        return badInput(e.what());
    } catch (const std::exception& e) {
        return badInput(std::string(e.what()));
    }
    return drawCatalogue(a, job, backend);
}

}  // namespace

int main(int argc, char** argv) {
    Arguments a;
    if (const Stop stop = parseArguments(argc, argv, a)) return *stop;
    if (!a.scene.empty()) return renderScene(a);
    if (a.stochasticGiven())
        return badInput(a.stochasticFlags() + ": only with --scene FILE.json (a \"stochastic\" scene)");
    if (a.shader.empty()) return badInput("give --shader NAME or --scene FILE.json");
    return renderCatalogue(a);
}
