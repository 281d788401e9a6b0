// glslang reflection into the plain tables the header embeds.
#include "reflection.hpp"

#include <glslang/Include/Types.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>

namespace prism::shaderc {

ProgramReflection reflectProgram(glslang::TProgram& program, const Contract& contract) {
    ProgramReflection r;
    if (!program.buildReflection(EShReflectionDefault)) return r;
    for (int i = 0; i < program.getNumPipeInputs(); ++i) {
        const auto& in = program.getPipeInput(i);
        ReflectedAttribute a{in.name, static_cast<std::uint32_t>(in.glDefineType), -1};
        if (a.name.rfind("gl_", 0) == 0) continue;
        for (const auto& c : contract.attributes)
            if (c.name == a.name) a.location = c.location;
        if (in.getType() && in.getType()->getQualifier().hasLocation())  // GL binds what the shader says
            a.location = static_cast<int>(in.getType()->getQualifier().layoutLocation);
        r.attributes.push_back(std::move(a));
    }
    for (int i = 0; i < program.getNumUniformVariables(); ++i) {
        const auto& u = program.getUniform(i);
        r.uniforms.push_back({u.name, static_cast<std::uint32_t>(u.glDefineType), std::max(1, u.size)});
    }
    std::sort(r.attributes.begin(), r.attributes.end(), [](const auto& a, const auto& b) {
        return a.location != b.location ? a.location < b.location : a.name < b.name;
    });
    std::sort(r.uniforms.begin(), r.uniforms.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return r;
}

}  // namespace prism::shaderc
