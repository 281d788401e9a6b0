// Compiling stages, binding contract attributes and linking a Program; compile and
// link failures become ShaderBuildError with file:line messages.
#include "prism/gl/program.hpp"

#include <algorithm>
#include <iostream>
#include <mutex>
#include <utility>

#include "prism/gl/gl.hpp"

namespace prism::gl {
namespace {

std::mutex gHandlerMutex;
WarningHandler gDefaultHandler;

WarningHandler defaultHandler() {
    std::lock_guard lock(gHandlerMutex);
    return gDefaultHandler;
}

GLenum shaderType(catalog::Stage stage) {
    switch (stage) {
        case catalog::Stage::Vertex: return GL_VERTEX_SHADER;
        case catalog::Stage::Geometry: return GL_GEOMETRY_SHADER;
        case catalog::Stage::Fragment: return GL_FRAGMENT_SHADER;
        case catalog::Stage::Compute: return GL_COMPUTE_SHADER;
        case catalog::Stage::TessControl: return GL_TESS_CONTROL_SHADER;
        case catalog::Stage::TessEvaluation: return GL_TESS_EVALUATION_SHADER;
        default: return GL_NONE;  // mesh, task and ray tracing: Vulkan-client stages, which GL cannot create
    }
}

std::string_view stageWord(catalog::Stage stage) {
    switch (stage) {
        case catalog::Stage::Vertex: return "vertex";
        case catalog::Stage::Geometry: return "geometry";
        case catalog::Stage::Fragment: return "fragment";
        case catalog::Stage::Compute: return "compute";
        case catalog::Stage::TessControl: return "tessellation control";
        case catalog::Stage::TessEvaluation: return "tessellation evaluation";
        case catalog::Stage::Mesh: return "mesh";
        case catalog::Stage::Task: return "task";
        default: return "ray-tracing";
    }
    return "?";
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 0)), '\0');
    if (length > 0) glGetShaderInfoLog(shader, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 0)), '\0');
    if (length > 0) glGetProgramInfoLog(program, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

std::string programName(const std::string& label) {
    return label.empty() ? "program" : "program '" + label + "'";
}

// What the linked program reads, as the driver reports it (not the reflection table: a
// program built from raw sources has none).
std::vector<AttributeBinding> activeAttributesOf(GLuint program) {
    GLint count = 0, maxLength = 0;
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &maxLength);
    std::vector<AttributeBinding> out;
    std::string name(static_cast<std::size_t>(std::max(maxLength, 1)), '\0');
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveAttrib(program, static_cast<GLuint>(i), static_cast<GLsizei>(name.size()), &length, &size, &type,
                          name.data());
        std::string attribute(name.data(), static_cast<std::size_t>(length));
        if (attribute.rfind("gl_", 0) == 0) continue;  // gl_VertexID and friends: fed by GL itself
        out.push_back({attribute, glGetAttribLocation(program, attribute.c_str())});
    }
    return out;
}

}  // namespace

void setDefaultWarningHandler(WarningHandler handler) {
    std::lock_guard lock(gHandlerMutex);
    gDefaultHandler = std::move(handler);
}

ProgramSources sourcesFromVariant(const catalog::Variant& variant,
                                  std::span<const catalog::Attribute> contractAttributes, std::string label) {
    ProgramSources out;
    out.label = label.empty() ? std::string(variant.name) : std::move(label);
    for (const auto& stage : variant.stages) {
        StageText text;
        text.stage = stage.stage;
        text.source = catalog::joinChunks(stage.chunks);
        for (const auto& f : stage.files) text.files.push_back({f.number, std::string(f.path)});
        out.stages.push_back(std::move(text));
    }
    for (const auto& a : contractAttributes) out.attributes.push_back({std::string(a.name), a.location});
    std::vector<UniformDecl> uniforms;
    for (const auto& u : variant.uniforms) uniforms.push_back({std::string(u.name), u.glType, u.arraySize});
    out.uniforms = std::move(uniforms);
    out.variant = &variant;
    return out;
}

Program::Program(const catalog::Variant& variant, std::span<const catalog::Attribute> contractAttributes,
                 std::string label) {
    build(sourcesFromVariant(variant, contractAttributes, std::move(label)));
}

Program::Program(ProgramSources sources) {
    build(std::move(sources));
}

void Program::use() const {
    glUseProgram(program_.id());
}

void Program::setWarningHandler(WarningHandler handler) {
    warningHandler_ = std::move(handler);
}

void Program::warn(const std::string& message) const {
    const std::string text = programName(label_) + ": " + message;
    if (warningHandler_) {
        warningHandler_(text);
    } else if (WarningHandler fallback = defaultHandler()) {
        fallback(text);
    } else {
        std::cerr << "prism: warning: " << text << std::endl;
    }
}

void Program::build(ProgramSources sources) {
    label_ = std::move(sources.label);
    variant_ = sources.variant;
    if (sources.stages.empty()) throw ShaderBuildError(programName(label_) + " has no stages", "");

    std::vector<ShaderObject> shaders;  // deleted when this function returns or throws
    for (const StageText& stage : sources.stages) {
        try {
            shaders.push_back(ShaderObject::create(shaderType(stage.stage)));
        } catch (const GlError&) {
            throw ShaderBuildError("prism: cannot create a " + std::string(stageWord(stage.stage)) + " shader for " +
                                       programName(label_) +
                                       " (is a GL context current, and does it support this stage?)",
                                   "");
        }
        const GLuint shader = shaders.back().id();
        const GLchar* text = stage.source.c_str();
        const GLint length = static_cast<GLint>(stage.source.size());
        glShaderSource(shader, 1, &text, &length);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        const std::string log = shaderLog(shader);
        if (!ok) {
            throw ShaderBuildError("prism: cannot compile the " + std::string(stageWord(stage.stage)) + " shader of " +
                                       programName(label_) + ":\n" + translateDriverLog(log, stage.files),
                                   log);
        }
        if (!log.empty())
            warn(std::string(stageWord(stage.stage)) + " shader compiled with messages:\n" +
                 translateDriverLog(log, stage.files));
    }

    program_ = ProgramObject::create();
    const GLuint program = program_.id();
    for (const auto& s : shaders) glAttachShader(program, s.id());
    for (const auto& a : sources.attributes)
        if (a.location >= 0) glBindAttribLocation(program, static_cast<GLuint>(a.location), a.name.c_str());
    glLinkProgram(program);
    for (const auto& s : shaders) glDetachShader(program, s.id());
    shaders.clear();

    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        const std::string log = programLog(program);
        program_.reset();
        throw ShaderBuildError("prism: cannot link " + programName(label_) + ":\n" + log, log);
    }
    try {
        throwIfGlError("building " + programName(label_));
    } catch (const GlError& e) {
        program_.reset();
        throw ShaderBuildError(e.what(), "");
    }
    activeAttributes_ = activeAttributesOf(program);
    buildUniformTable(sources.uniforms);
    startUnsetCheck(sources.stages);
}

}  // namespace prism::gl
