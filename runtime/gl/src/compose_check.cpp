// Checks a composed program with prism-shaderc's own stages (prism/shaderc/build_step.hpp):
// the catalogue's contract is turned back into the build step's contract, each composed
// stage into a flattened stage with its files table, and checkProgram() does the rest.
#include "compose_check.hpp"

#include "prism/shaderc/build_step.hpp"

namespace prism::gl::detail {
namespace {

// GLSL type names the contract may use, for turning GL enums back into names.
constexpr const char* kGlslTypes[] = {"float",      "vec2",       "vec3",          "vec4",           "int",
                                      "ivec2",      "ivec3",      "ivec4",         "uint",           "uvec2",
                                      "uvec3",      "uvec4",      "bool",          "bvec2",          "bvec3",
                                      "bvec4",      "mat2",       "mat3",          "mat4",           "mat2x3",
                                      "mat2x4",     "mat3x2",     "mat3x4",        "mat4x2",         "mat4x3",
                                      "sampler2D",  "sampler3D",  "samplerCube",   "sampler2DArray", "sampler2DShadow",
                                      "isampler2D", "usampler2D", "samplerBuffer", "image2D"};

std::string glslTypeName(std::uint32_t glType) {
    for (const char* name : kGlslTypes)
        if (shaderc::glTypeOf(name) == glType) return name;
    return "float";
}

shaderc::BindingContract contractOf(const catalog::Catalog& c, std::span<const std::string> files) {
    shaderc::BindingContract contract;
    contract.files.assign(files.begin(), files.end());
    for (const auto& a : c.contractAttributes)
        contract.attributes.push_back({std::string(a.name), glslTypeName(a.glType), a.glType, a.location, 0});
    for (const auto& u : c.contractUniforms)
        contract.uniforms.push_back(
            {std::string(u.name), glslTypeName(u.glType), u.glType, 0, u.arraySize > 1 ? u.arraySize : 0});
    return contract;
}

}  // namespace

std::vector<std::string> checkComposedSources(const catalog::Catalog& catalog, const ProgramSources& sources,
                                              std::span<const std::string> contractFiles) {
    static const shaderc::Validator validator;  // glslang's state, for the process
    std::vector<shaderc::StageToCheck> stages;
    for (const auto& s : sources.stages) {
        shaderc::StageToCheck v;
        v.stage = s.stage;
        v.path = s.files.empty() ? sources.label : s.files.front().path;
        v.resolved.text = s.source;
        for (const auto& f : s.files) {
            if (v.resolved.files.size() <= f.number) v.resolved.files.resize(f.number + 1);
            v.resolved.files[f.number] = f.path;
        }
        stages.push_back(std::move(v));
    }
    const shaderc::ProgramCheck result = shaderc::checkProgram(stages, contractOf(catalog, contractFiles));
    std::vector<std::string> out;
    if (result.ok) return out;
    for (const auto& m : result.messages) out.push_back(m.text);
    if (out.empty()) out.push_back(sources.label + ": error: the composed program failed validation");
    return out;
}

CompositionError compositionError(const std::string& heading, std::span<const shaderc::Message> messages) {
    std::vector<std::string> lines;
    std::string text = heading;
    for (const auto& m : messages) {
        lines.push_back(m.text);
        text += "\n" + m.text;
    }
    return CompositionError(text, std::move(lines));
}

}  // namespace prism::gl::detail
