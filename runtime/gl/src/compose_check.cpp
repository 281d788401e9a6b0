// Checks a composed program with prism-shaderc's own stages (see compose_check.hpp): the
// catalogue's contract is turned back into the tool's Contract, each composed stage into
// a resolved stage with its line table, and validateProgram() does the rest.
#include "compose_check.hpp"

#include <cctype>
#include <mutex>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "validator.hpp"

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

shaderc::Contract contractOf(const catalog::Catalog& c) {
    shaderc::Contract contract;
    contract.files.push_back("<the catalogue's contract>");
    for (const auto& a : c.contractAttributes)
        contract.attributes.push_back({std::string(a.name), glslTypeName(a.glType), a.location});
    for (const auto& u : c.contractUniforms)
        contract.uniforms.push_back({std::string(u.name), glslTypeName(u.glType), u.arraySize > 1 ? u.arraySize : 0});
    return contract;
}

int versionNumberOf(const std::string& source) {
    std::size_t p = source.find("#version");
    if (p == std::string::npos) return 110;
    p = source.find_first_of("0123456789", p);
    int v = 0;
    while (p < source.size() && std::isdigit(static_cast<unsigned char>(source[p]))) v = v * 10 + (source[p++] - '0');
    return v;
}

std::string firstLine(const std::string& s) {
    return s.substr(0, s.find('\n'));
}

void initializeOnce() {
    static std::once_flag once;
    std::call_once(once, [] { shaderc::initializeValidator(); });
}

}  // namespace

std::vector<std::string> checkComposedSources(const catalog::Catalog& catalog, const ProgramSources& sources) {
    initializeOnce();
    std::vector<shaderc::StageToValidate> stages;
    for (const auto& s : sources.stages) {
        shaderc::StageToValidate v;
        v.stage = s.stage;
        v.path = s.files.empty() ? sources.label : s.files.front().path;
        v.resolved.text = s.source;
        v.resolved.versionDirective = firstLine(s.source);
        v.resolved.versionNumber = versionNumberOf(s.source);
        for (const auto& f : s.files) {
            shaderc::ResolvedFile file;
            file.number = f.number;
            file.path = f.path;
            file.canonical = f.path;
            v.resolved.files.push_back(std::move(file));
        }
        stages.push_back(std::move(v));
    }
    const shaderc::ValidatedVariant result = shaderc::validateProgram(stages, contractOf(catalog));
    bool anyError = false;
    for (const auto& d : result.diagnostics) anyError = anyError || d.severity == shaderc::Severity::Error;
    std::vector<std::string> out;
    if (!anyError && result.ok) return out;
    for (const auto& d : result.diagnostics) out.push_back(shaderc::formatDiagnostic(d, shaderc::ErrorFormat::Gcc));
    if (out.empty()) out.push_back(sources.label + ": error: the composed program failed validation");
    return out;
}

}  // namespace prism::gl::detail
