// A Program's uniform table (from reflection or the driver) and its checked setters:
// unknown names and unfitting types are reported once per (program, name).
#include <cstdio>
#include <cstdlib>
#include <functional>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "prism/gl/gl.hpp"
#include "prism/gl/program.hpp"
#include "uniform_gl_types.hpp"

namespace prism::gl {

// What a setter passes, to check it against the uniform's GLSL type.
enum class detail::UniformSetterKind : int {
    Float,
    Int,
    Unsigned,
    Bool,
    Vec2,
    Vec3,
    Vec4,
    IVec2,
    IVec3,
    IVec4,
    Mat3,
    Mat4
};

namespace {

using Kind = detail::UniformSetterKind;

bool fits(Kind kind, std::uint32_t t) {
    if (t == 0) return true;  // type unknown: nothing to check
    switch (kind) {
        case Kind::Float: return t == GL_FLOAT;
        case Kind::Int: return t == GL_INT || t == GL_BOOL || detail::isSamplerType(t);
        case Kind::Unsigned: return t == GL_UNSIGNED_INT || t == GL_BOOL;
        case Kind::Bool: return t == GL_BOOL || t == GL_INT || t == GL_UNSIGNED_INT;
        case Kind::Vec2: return t == GL_FLOAT_VEC2;
        case Kind::Vec3: return t == GL_FLOAT_VEC3;
        case Kind::Vec4: return t == GL_FLOAT_VEC4;
        case Kind::IVec2: return t == GL_INT_VEC2 || t == GL_BOOL_VEC2;
        case Kind::IVec3: return t == GL_INT_VEC3 || t == GL_BOOL_VEC3;
        case Kind::IVec4: return t == GL_INT_VEC4 || t == GL_BOOL_VEC4;
        case Kind::Mat3: return t == GL_FLOAT_MAT3;
        case Kind::Mat4: return t == GL_FLOAT_MAT4;
    }
    return false;
}

std::string_view kindName(Kind kind) {
    switch (kind) {
        case Kind::Float: return "float";
        case Kind::Int: return "int";
        case Kind::Unsigned: return "unsigned";
        case Kind::Bool: return "bool";
        case Kind::Vec2: return "vec2";
        case Kind::Vec3: return "vec3";
        case Kind::Vec4: return "vec4";
        case Kind::IVec2: return "ivec2";
        case Kind::IVec3: return "ivec3";
        case Kind::IVec4: return "ivec4";
        case Kind::Mat3: return "mat3";
        case Kind::Mat4: return "mat4";
    }
    return "?";
}

std::string glslTypeName(std::uint32_t t) {
    switch (t) {
        case GL_FLOAT: return "float";
        case GL_FLOAT_VEC2: return "vec2";
        case GL_FLOAT_VEC3: return "vec3";
        case GL_FLOAT_VEC4: return "vec4";
        case GL_INT: return "int";
        case GL_INT_VEC2: return "ivec2";
        case GL_INT_VEC3: return "ivec3";
        case GL_INT_VEC4: return "ivec4";
        case GL_UNSIGNED_INT: return "uint";
        case GL_BOOL: return "bool";
        case GL_FLOAT_MAT2: return "mat2";
        case GL_FLOAT_MAT3: return "mat3";
        case GL_FLOAT_MAT4: return "mat4";
        default: {
            if (detail::isSamplerType(t)) return "a sampler";
            char text[32];
            std::snprintf(text, sizeof text, "GL type 0x%04x", static_cast<unsigned>(t));
            return text;
        }
    }
}

// "a[0]" -> "a"; anything else unchanged.
std::string withoutFirstIndex(const std::string& name) {
    constexpr std::string_view suffix = "[0]";
    if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        return name.substr(0, name.size() - suffix.size());
    return name;
}

}  // namespace

bool detail::isSamplerType(std::uint32_t t) {
    switch (t) {
        case GL_SAMPLER_1D:
        case GL_SAMPLER_2D:
        case GL_SAMPLER_3D:
        case GL_SAMPLER_CUBE:
        case GL_SAMPLER_1D_SHADOW:
        case GL_SAMPLER_2D_SHADOW:
        case GL_SAMPLER_1D_ARRAY:
        case GL_SAMPLER_2D_ARRAY:
        case GL_SAMPLER_1D_ARRAY_SHADOW:
        case GL_SAMPLER_2D_ARRAY_SHADOW:
        case GL_SAMPLER_2D_MULTISAMPLE:
        case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
        case GL_SAMPLER_CUBE_SHADOW:
        case GL_SAMPLER_BUFFER:
        case GL_SAMPLER_2D_RECT:
        case GL_SAMPLER_2D_RECT_SHADOW:
        case GL_INT_SAMPLER_1D:
        case GL_INT_SAMPLER_2D:
        case GL_INT_SAMPLER_3D:
        case GL_INT_SAMPLER_CUBE:
        case GL_INT_SAMPLER_1D_ARRAY:
        case GL_INT_SAMPLER_2D_ARRAY:
        case GL_INT_SAMPLER_2D_MULTISAMPLE:
        case GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
        case GL_INT_SAMPLER_BUFFER:
        case GL_INT_SAMPLER_2D_RECT:
        case GL_UNSIGNED_INT_SAMPLER_1D:
        case GL_UNSIGNED_INT_SAMPLER_2D:
        case GL_UNSIGNED_INT_SAMPLER_3D:
        case GL_UNSIGNED_INT_SAMPLER_CUBE:
        case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY:
        case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
        case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE:
        case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
        case GL_UNSIGNED_INT_SAMPLER_BUFFER:
        case GL_UNSIGNED_INT_SAMPLER_2D_RECT: return true;
        default: return false;
    }
}

void Program::addUniform(const std::string& reflectedName, std::uint32_t glType, int arraySize) {
    const std::string base = withoutFirstIndex(reflectedName);
    const bool isArray = arraySize > 1 || base != reflectedName;
    declared_.push_back({base, glType});
    if (!isArray) {
        uniforms_[base] = {glGetUniformLocation(program_.id(), base.c_str()), glType, 1};
        return;
    }
    const int n = std::max(arraySize, 1);
    for (int i = 0; i < n; ++i) {
        const std::string element = base + "[" + std::to_string(i) + "]";
        uniforms_[element] = {glGetUniformLocation(program_.id(), element.c_str()), glType, n - i};
    }
    uniforms_[base] = uniforms_[base + "[0]"];
}

void Program::buildUniformTable(const std::optional<std::vector<UniformDecl>>& reflected) {
    uniforms_.clear();
    declared_.clear();
    if (reflected) {
        for (const auto& u : *reflected) addUniform(u.name, u.glType, u.arraySize);
        return;
    }
    GLint count = 0, maxLength = 0;
    glGetProgramiv(program_.id(), GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(program_.id(), GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxLength);
    std::string name(static_cast<std::size_t>(std::max(maxLength, 1)), '\0');
    for (GLint i = 0; i < count; ++i) {
        GLsizei length = 0;
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program_.id(), static_cast<GLuint>(i), maxLength, &length, &size, &type, name.data());
        const std::string uniformName = name.substr(0, static_cast<std::size_t>(length));
        if (glGetUniformLocation(program_.id(), uniformName.c_str()) < 0) continue;  // uniform-block member
        addUniform(uniformName, type, size);
    }
}

const Program::UniformSlot* Program::slotFor(std::string_view name) {
    if (auto it = uniforms_.find(name); it != uniforms_.end()) return &it->second;
    // Not in the table (e.g. a struct member path): ask the driver once and cache a hit.
    const std::string key(name);
    const GLint location = glGetUniformLocation(program_.id(), key.c_str());
    if (location < 0) return nullptr;
    return &(uniforms_[key] = UniformSlot{location, 0, 1});
}

const Program::UniformSlot* Program::prepare(std::string_view name, SetterKind kind, std::size_t count) {
    const UniformSlot* slot = slotFor(name);
    if (!slot) {
        if (reported_.emplace(name).second) {
            unknownReports_.emplace_back(name);
            warn("set() of uniform '" + std::string(name) + "' which the program does not have" +
                 catalog::didYouMean(name, uniformNames()) +
                 " (misspelt, or not used by this variant); the value is ignored. Reported once.");
        }
        return nullptr;
    }
    if (!fits(kind, slot->glType)) {
        if (reported_.emplace(name).second) {
            mismatchReports_.emplace_back(name);
            warn("uniform '" + std::string(name) + "' is " + glslTypeName(slot->glType) + " but set() got a " +
                 std::string(kindName(kind)) + "; the value is ignored. Reported once.");
        }
        return nullptr;
    }
    if (count > static_cast<std::size_t>(slot->elements))
        throw std::length_error("prism: " + (label_.empty() ? std::string("program") : "program '" + label_ + "'") +
                                ": set() of " + std::to_string(count) + " elements into uniform '" + std::string(name) +
                                "', which has room for " + std::to_string(slot->elements));
    use();
    setSinceLink_.emplace(name.substr(0, name.back() == ']' ? name.rfind('[') : name.size()));
    return slot;
}

bool Program::builtFrom(const catalog::Shader& shader) const {
    // The variant lies in its shader's variant table: two pointer comparisons, no names.
    const std::less<const catalog::Variant*> before;
    return variant_ != nullptr && !before(variant_, shader.variants.data()) &&
           before(variant_, shader.variants.data() + shader.variants.size());
}

bool Program::takesHandleOf(const catalog::Shader& shader, std::string_view uniform) {
    if (variant_ == nullptr || builtFrom(shader)) return true;
    const std::string handle = std::string(shader.name) + "::" + std::string(uniform);  // no GLSL name has "::"
    if (reported_.emplace(handle).second) {
        foreignReports_.push_back(handle);
        warn("set() of handle " + handle + ", which belongs to shader '" + std::string(shader.name) +
             "', on a program of another shader; the value is ignored (use this shader's handle, or "
             "ProgramOf<Shader> to catch it at compile time). Reported once.");
    }
    return false;
}

void Program::set(std::string_view name, float v) {
    if (auto s = prepare(name, SetterKind::Float, 1)) glUniform1f(s->location, v);
}
void Program::set(std::string_view name, int v) {
    constexpr int kExactInFloat = 1 << 24;  // every int up to here is a float without loss
    if (const UniformSlot* slot = slotFor(name); slot && slot->glType == GL_FLOAT && std::abs(v) <= kExactInFloat) {
        set(name, static_cast<float>(v));  // set("u_bands", 4) on a float: the literal's value, not a drop
        return;
    }
    if (auto s = prepare(name, SetterKind::Int, 1)) glUniform1i(s->location, v);
}
void Program::set(std::string_view name, unsigned v) {
    if (auto s = prepare(name, SetterKind::Unsigned, 1)) glUniform1ui(s->location, v);
}
void Program::set(std::string_view name, bool v) {
    if (auto s = prepare(name, SetterKind::Bool, 1)) glUniform1i(s->location, v ? 1 : 0);
}
void Program::set(std::string_view name, const glm::vec2& v) {
    if (auto s = prepare(name, SetterKind::Vec2, 1)) glUniform2fv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec3& v) {
    if (auto s = prepare(name, SetterKind::Vec3, 1)) glUniform3fv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::vec4& v) {
    if (auto s = prepare(name, SetterKind::Vec4, 1)) glUniform4fv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::ivec2& v) {
    if (auto s = prepare(name, SetterKind::IVec2, 1)) glUniform2iv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::ivec3& v) {
    if (auto s = prepare(name, SetterKind::IVec3, 1)) glUniform3iv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::ivec4& v) {
    if (auto s = prepare(name, SetterKind::IVec4, 1)) glUniform4iv(s->location, 1, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat3& v) {
    if (auto s = prepare(name, SetterKind::Mat3, 1)) glUniformMatrix3fv(s->location, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(std::string_view name, const glm::mat4& v) {
    if (auto s = prepare(name, SetterKind::Mat4, 1)) glUniformMatrix4fv(s->location, 1, GL_FALSE, glm::value_ptr(v));
}

void Program::set(std::string_view name, std::span<const float> v) {
    if (auto s = prepare(name, SetterKind::Float, v.size()); s && !v.empty())
        glUniform1fv(s->location, static_cast<GLsizei>(v.size()), v.data());
}
void Program::set(std::string_view name, std::span<const int> v) {
    if (auto s = prepare(name, SetterKind::Int, v.size()); s && !v.empty())
        glUniform1iv(s->location, static_cast<GLsizei>(v.size()), v.data());
}
void Program::set(std::string_view name, std::span<const glm::vec2> v) {
    if (auto s = prepare(name, SetterKind::Vec2, v.size()); s && !v.empty())
        glUniform2fv(s->location, static_cast<GLsizei>(v.size()), glm::value_ptr(v.front()));
}
void Program::set(std::string_view name, std::span<const glm::vec3> v) {
    if (auto s = prepare(name, SetterKind::Vec3, v.size()); s && !v.empty())
        glUniform3fv(s->location, static_cast<GLsizei>(v.size()), glm::value_ptr(v.front()));
}
void Program::set(std::string_view name, std::span<const glm::vec4> v) {
    if (auto s = prepare(name, SetterKind::Vec4, v.size()); s && !v.empty())
        glUniform4fv(s->location, static_cast<GLsizei>(v.size()), glm::value_ptr(v.front()));
}
void Program::set(std::string_view name, std::span<const glm::mat3> v) {
    if (auto s = prepare(name, SetterKind::Mat3, v.size()); s && !v.empty())
        glUniformMatrix3fv(s->location, static_cast<GLsizei>(v.size()), GL_FALSE, glm::value_ptr(v.front()));
}
void Program::set(std::string_view name, std::span<const glm::mat4> v) {
    if (auto s = prepare(name, SetterKind::Mat4, v.size()); s && !v.empty())
        glUniformMatrix4fv(s->location, static_cast<GLsizei>(v.size()), GL_FALSE, glm::value_ptr(v.front()));
}

std::vector<std::string> Program::uniformNames() const {
    std::vector<std::string> names;
    for (const auto& u : declared_) names.push_back(u.name);
    return names;
}

bool Program::hasUniform(std::string_view name) const {
    if (uniforms_.find(name) != uniforms_.end()) return true;
    return glGetUniformLocation(program_.id(), std::string(name).c_str()) >= 0;
}

int Program::uniformLocation(std::string_view name) const {
    if (auto it = uniforms_.find(name); it != uniforms_.end()) return it->second.location;
    return glGetUniformLocation(program_.id(), std::string(name).c_str());
}

}  // namespace prism::gl
