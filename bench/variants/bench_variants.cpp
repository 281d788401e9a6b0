// prism_bench_variants: what "model only what the scene requires" saves. For each
// example scene it compares the minimal variants the runtime picks (light loops bounded
// by the scene's counts, fog code only with fog) with an "everything on" uber-shader
// (DIRECTIONAL_LIGHTS=8, POINT_LIGHTS=4, FOG=1, the counts and fog density set so the
// image is the same) on: lines of the compiled GLSL (after the preprocessor), active
// uniforms (as the driver reports them), compile + link time, and frame time on llvmpipe.
//   prism_bench_variants [--runs N] [--frames N] [--csv FILE] scene.json...
// Prints a Markdown table; medians of N runs, measured in one run of the program.
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <filesystem>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "prism/render/feature_variants.hpp"
#include "prism/render/frame_uniforms.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/image/image_compare.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

EShLanguage glslangStage(prism::catalog::Stage s) {
    switch (s) {
        case prism::catalog::Stage::Vertex: return EShLangVertex;
        case prism::catalog::Stage::Geometry: return EShLangGeometry;
        case prism::catalog::Stage::Fragment: return EShLangFragment;
        default: return EShLangCompute;
    }
}

// Lines of code the compiler sees after preprocessing: no blank lines, no directives.
int preprocessedLines(const prism::catalog::Variant& v) {
    int lines = 0;
    for (const auto& st : v.stages) {
        const std::string text = prism::catalog::joinChunks(st.chunks);
        const char* s = text.c_str();
        glslang::TShader shader(glslangStage(st.stage));
        shader.setStrings(&s, 1);
        std::string out;
        glslang::TShader::ForbidIncluder includer;
        if (!shader.preprocess(GetDefaultResources(), 330, ECoreProfile, false, false, EShMsgDefault, &out, includer))
            throw std::runtime_error("glslang could not preprocess " + std::string(v.name));
        std::istringstream in(out);
        for (std::string line; std::getline(in, line);) {
            auto first = line.find_first_not_of(" \t");
            if (first != std::string::npos && line[first] != '#') ++lines;
        }
    }
    return lines;
}

struct Draw {
    const prism::scene::SceneObject* object;
    const prism::catalog::Variant* variant;
    std::unique_ptr<prism::render::GpuMesh> mesh;
};

struct ModeResult {
    int glslLines = 0, activeUniforms = 0;
    std::size_t programs = 0;
    double compileLinkMs = 0.0, frameMs = 0.0;
    prism::image::Image8 image;
};

ModeResult measure(const prism::scene::Scene& scene, const prism::render::FeatureSet& features, bool uber, int runs,
                   int frames) {
    ModeResult r;
    std::vector<Draw> draws;
    std::map<std::string, const prism::catalog::Variant*> distinct;
    prism::render::ProgramCache names(prism::shaders::kCatalog);
    for (const auto& o : scene.objects) {
        const auto* shader = prism::catalog::findShader(prism::shaders::kCatalog, o.shader);
        if (!shader) throw std::runtime_error("unknown shader " + o.shader);
        const prism::render::FeatureSet f = uber ? prism::render::FeatureSet{8, 4, true} : features;
        const auto& variant = names.variantOf(o.shader, prism::render::variantFor(*shader, f, o.variantOverrides));
        distinct[o.shader + " " + std::string(variant.name)] = &variant;
        draws.push_back({&o, &variant,
                         std::make_unique<prism::render::GpuMesh>(
                             prism::render::meshForShader(o.shader, prism::render::namedMesh(o.mesh, o.subdivision)),
                             prism::shaders::kCatalog.contractAttributes)});
    }
    r.programs = distinct.size();
    // Compile + link of every distinct program, median over runs (shader cache disabled).
    std::vector<double> buildTimes;
    std::map<const prism::catalog::Variant*, std::unique_ptr<prism::gl::Program>> programs;
    for (int run = 0; run < runs; ++run) {
        const auto start = Clock::now();
        for (const auto& [key, variant] : distinct)
            programs[variant] =
                std::make_unique<prism::gl::Program>(*variant, prism::shaders::kCatalog.contractAttributes, key);
        glFinish();
        buildTimes.push_back(msSince(start));
    }
    r.compileLinkMs = median(buildTimes);
    for (const auto& [key, variant] : distinct) {
        r.glslLines += preprocessedLines(*variant);
        GLint n = 0;
        glGetProgramiv(programs[variant]->id(), GL_ACTIVE_UNIFORMS, &n);
        r.activeUniforms += n;
    }
    // Frames: the same scene drawn with these programs; fog density 0 when the scene has none.
    const prism::view::Fog noFog{glm::vec3(0.0f), 0.0f};
    const prism::view::Fog* fog = scene.fog ? &*scene.fog : (uber ? &noFog : nullptr);
    prism::gl::Framebuffer fb(scene.width, scene.height);
    std::vector<double> frameTimes;
    for (int frame = 0; frame < frames + 2; ++frame) {
        const auto start = Clock::now();
        fb.bind();
        const glm::vec4 bg = scene.fog ? glm::vec4(scene.fog->color, 1.0f) : scene.background;
        fb.clear({bg.r, bg.g, bg.b, bg.a});
        glEnable(GL_DEPTH_TEST);
        for (const auto& d : draws) {
            auto& program = *programs[d.variant];
            program.use();
            prism::render::setFrameUniforms(program, scene.camera, float(scene.width) / float(scene.height),
                                            scene.lights, d.object->world, d.object->material, fog);
            d.mesh->draw();
        }
        glFinish();
        if (frame >= 2) frameTimes.push_back(msSince(start));  // two warm-up frames
    }
    r.frameMs = median(frameTimes);
    r.image = fb.readImage8();
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 7, frames = 15;
    std::string csvPath;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--frames" && i + 1 < argc)
            frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--csv" && i + 1 < argc)
            csvPath = argv[++i];
        else
            scenes.push_back(a);
    }
    if (scenes.empty()) {
        std::cerr << "usage: prism_bench_variants [--runs N] [--frames N] [--csv FILE] scene.json...\n";
        return 2;
    }
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);  // measure real compiles
    glslang::InitializeProcess();
    auto context = prism::gl::createContext();
    std::ostringstream csv;
    csv << "scene,mode,programs,glsl_lines,active_uniforms,compile_link_ms,frame_ms,max_pixel_diff\n";
    std::cout << "| scene | mode | programs | GLSL lines | active uniforms | compile+link ms | frame ms | "
                 "image diff (max/255) |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
    std::cout << std::fixed << std::setprecision(2);
    for (const auto& path : scenes) {
        const auto scene = prism::scene::loadScene(path);
        const auto features = prism::render::featuresOf(scene.lights, scene.fog.has_value());
        const auto name = std::filesystem::path(path).stem().string();
        auto minimal = measure(scene, features, false, runs, frames);
        auto uber = measure(scene, features, true, runs, frames);
        const int diff = prism::image::compareImages(minimal.image, uber.image).maxChannelDiff;
        for (const auto* m : {&minimal, &uber}) {
            const char* mode = m == &minimal ? "minimal" : "uber";
            std::cout << "| " << name << " | " << mode << " | " << m->programs << " | " << m->glslLines << " | "
                      << m->activeUniforms << " | " << m->compileLinkMs << " | " << m->frameMs << " | " << diff
                      << " |\n";
            csv << name << "," << mode << "," << m->programs << "," << m->glslLines << "," << m->activeUniforms << ","
                << m->compileLinkMs << "," << m->frameMs << "," << diff << "\n";
        }
        std::cout << "| " << name << " | uber / minimal | | " << double(uber.glslLines) / minimal.glslLines << "x | "
                  << double(uber.activeUniforms) / minimal.activeUniforms << "x | "
                  << uber.compileLinkMs / minimal.compileLinkMs << "x | " << uber.frameMs / minimal.frameMs
                  << "x | |\n";
    }
    if (!csvPath.empty()) std::ofstream(csvPath) << csv.str();
    glslang::FinalizeProcess();
    return 0;
}
