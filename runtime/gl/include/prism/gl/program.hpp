// Linked GL programs built from the shader catalogue (or from raw stage sources),
// with driver errors mapped back to module files and checked uniform setters.
//
// Usage (snippet: examples/snippets/gl_program.cpp):
//
//     #include <vector>
//
//     #include "prism/gl/program.hpp"
//     #include "prism/shaders.hpp"  // generated catalogue
//     const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
//     const auto* variant = prism::catalog::findVariant(phong, {{"FOG", "1"}, {"DIRECTIONAL_LIGHTS", "4"}});
//     if (variant == nullptr) return 1;  // not generated; a misspelled axis or value throws instead
//     prism::gl::Program program(*variant, prism::shaders::kCatalog.contractAttributes, "phong");
//
//     program.use();
//     program.set("u_color", glm::vec4(1, 0, 0, 1));
//     std::vector<glm::vec3> dirs{{0, -1, 0}, {1, -1, 0}};
//     program.set("u_lightDirection", std::span<const glm::vec3>(dirs));  // array from element 0
//     program.set("u_lightDirection[2]", glm::vec3(0, 1, 0));             // one element
//
// Building: every stage is compiled, each contract attribute is bound to its
// location with glBindAttribLocation, then the program is linked. A compile or link
// failure throws prism::gl::ShaderBuildError whose message has the driver's log
// translated to `path:line:column: error: ...` through the stage's files table
// (see prism/gl/driver_log.hpp). Needs a current context; move-only.
//
// Uniforms: locations come from the variant's reflection table once, at link time
// (an array `a` of n elements also answers to `a[0]`..`a[n-1]`). Programs built from
// raw sources without a table ask the driver for its active uniforms instead. A name
// missing from the table is looked up in the driver once (struct members such as
// `lights[1].color`) and cached. Every set() makes this program current.
// A uniform the program does not have, or a set() whose C++ type does not fit the
// uniform's GLSL type, is reported ONCE per (program, name) through the warning
// handler (stderr by default) and recorded in unknownUniformReports() /
// typeMismatchReports(); the set is then skipped (an unknown name's report says "did you
// mean" the nearest uniform). An int into a float uniform is no mismatch: it is set as
// the float of the same value when that is exact (|v| <= 2^24). A uniform that exists in
// the table but was optimised away by the driver (location -1) is set silently as a
// no-op, as GL does. Too many array elements throw std::length_error.
//
// Typed uniforms: set(handle, value) with the handles a generated header declares
// (prism/catalog/uniform_handle.hpp) checks the name, the value's C++ type and, through
// ProgramOf<Shader>, the shader at compile time. A plain Program checks the shader at run
// time: one built from a catalogue variant knows its shader (builtFrom), and a handle of
// another shader is reported once per handle, like an unknown name, and skipped.
// set(name, value) stays for names known only at run time. unsetUniforms() lists the
// active uniforms never set since link.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <glm/mat3x3.hpp>  // complete types for set() and the usage example
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "prism/gl/driver_log.hpp"
#include "prism/gl/handles.hpp"
#include "prism/catalog/shader_catalog.hpp"
#include "prism/catalog/uniform_handle.hpp"

namespace prism::gl {

namespace detail {
enum class UniformSetterKind : int;  // what a set() overload passes; defined in program_uniforms.cpp

// The C++ type set(handle, value) takes for a uniform of GLSL type T (void: no setter).
template <catalog::GlslType T>
struct UniformValue {
    using type = void;
};
#define PRISM_GL_UNIFORM_VALUE(Glsl, Cpp)          \
    template <>                                    \
    struct UniformValue<catalog::GlslType::Glsl> { \
        using type = Cpp;                          \
    }
PRISM_GL_UNIFORM_VALUE(Float, float);
PRISM_GL_UNIFORM_VALUE(Vec2, glm::vec2);
PRISM_GL_UNIFORM_VALUE(Vec3, glm::vec3);
PRISM_GL_UNIFORM_VALUE(Vec4, glm::vec4);
PRISM_GL_UNIFORM_VALUE(Int, int);
PRISM_GL_UNIFORM_VALUE(IVec2, glm::ivec2);
PRISM_GL_UNIFORM_VALUE(IVec3, glm::ivec3);
PRISM_GL_UNIFORM_VALUE(IVec4, glm::ivec4);
PRISM_GL_UNIFORM_VALUE(UInt, unsigned);
PRISM_GL_UNIFORM_VALUE(Bool, bool);
PRISM_GL_UNIFORM_VALUE(Mat3, glm::mat3);
PRISM_GL_UNIFORM_VALUE(Mat4, glm::mat4);
PRISM_GL_UNIFORM_VALUE(Sampler, int);  // the texture unit
#undef PRISM_GL_UNIFORM_VALUE

template <class>
inline constexpr bool kAlwaysFalse = false;
}  // namespace detail

// The source of one stage with its source-number table.
struct StageText {
    catalog::Stage stage = catalog::Stage::Vertex;
    std::string source;
    std::vector<SourceName> files;
};

struct AttributeBinding {
    std::string name;
    int location = 0;
};

struct UniformDecl {
    std::string name;          // as reflected: "u_color", "u_lights" or "u_lights[0]"
    std::uint32_t glType = 0;  // GL_FLOAT_VEC3 etc.; 0 = unknown (no type check)
    int arraySize = 1;
};

// Everything needed to build a Program without a catalogue variant.
struct ProgramSources {
    std::string label;                                 // names the program in errors and warnings
    std::vector<StageText> stages;                     // in pipeline order
    std::vector<AttributeBinding> attributes;          // bound before linking
    std::optional<std::vector<UniformDecl>> uniforms;  // reflection; nullopt = ask the driver
    const catalog::Variant* variant = nullptr;         // the catalogue variant these are, if any
};

// The catalogue variant's stages (chunks joined), contract attributes and uniforms.
ProgramSources sourcesFromVariant(const catalog::Variant& variant,
                                  std::span<const catalog::Attribute> contractAttributes, std::string label = {});

// Thrown when a stage fails to compile or the program fails to link.
class ShaderBuildError : public std::runtime_error {
  public:
    ShaderBuildError(const std::string& message, std::string driverLog)
        : std::runtime_error(message), driverLog_(std::move(driverLog)) {}
    const std::string& driverLog() const { return driverLog_; }  // untranslated

  private:
    std::string driverLog_;
};

using WarningHandler = std::function<void(std::string_view message)>;

// The handler new Programs start with; an empty function restores the default,
// which writes "prism: warning: ..." lines to stderr.
void setDefaultWarningHandler(WarningHandler handler);

class Program {
  public:
    Program(const catalog::Variant& variant, std::span<const catalog::Attribute> contractAttributes,
            std::string label = {});
    explicit Program(ProgramSources sources);
    Program(Program&& other) noexcept = default;
    Program& operator=(Program&& other) noexcept = default;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const;
    unsigned id() const { return program_.id(); }
    const std::string& label() const { return label_; }

    // The vertex attributes the linked program reads (the driver's active attributes,
    // gl_ built-ins left out) at the locations they were linked to.
    const std::vector<AttributeBinding>& activeAttributes() const { return activeAttributes_; }

    bool hasUniform(std::string_view name) const;
    int uniformLocation(std::string_view name) const;  // -1 when unknown or optimised away

    void set(std::string_view name, float value);
    void set(std::string_view name, double value) { set(name, static_cast<float>(value)); }
    void set(std::string_view name, int value);  // also bool and sampler uniforms
    void set(std::string_view name, unsigned value);
    void set(std::string_view name, bool value);
    void set(std::string_view name, const glm::vec2& value);
    void set(std::string_view name, const glm::vec3& value);
    void set(std::string_view name, const glm::vec4& value);
    void set(std::string_view name, const glm::ivec2& value);
    void set(std::string_view name, const glm::ivec3& value);
    void set(std::string_view name, const glm::ivec4& value);
    void set(std::string_view name, const glm::mat3& value);
    void set(std::string_view name, const glm::mat4& value);
    void set(std::string_view name, std::span<const float> values);
    void set(std::string_view name, std::span<const int> values);
    void set(std::string_view name, std::span<const glm::vec2> values);
    void set(std::string_view name, std::span<const glm::vec3> values);
    void set(std::string_view name, std::span<const glm::vec4> values);
    void set(std::string_view name, std::span<const glm::mat3> values);
    void set(std::string_view name, std::span<const glm::mat4> values);

    // Typed set (prism/catalog/uniform_handle.hpp): `value` must be exactly the C++ type of
    // the uniform's GLSL type (float, glm::vec3, int for a sampler's unit, ...), or for an
    // array a range of it (std::span, std::vector, std::array); anything else is a compile
    // error. A uniform this variant compiled out is a no-op, listed in compiledOutUniforms().
    // A handle of another shader than builtFrom()'s is skipped and reported once
    // (foreignHandleReports()); ProgramOf<Shader> rejects it at compile time instead.
    template <catalog::GlslType T, std::size_t N, class Tag, class V>
    void set(const catalog::UniformHandle<T, N, Tag>& uniform, const V& value) {
        using Element = typename detail::UniformValue<T>::type;
        static_assert(!std::is_void_v<Element>, "Program::set(handle, value): no setter for this GLSL type");
        if constexpr (catalog::CatalogShaderTag<Tag>)
            if (!takesHandleOf(catalog::shaderOf<Tag>(), uniform.name)) return;
        if constexpr (N == 1) {
            static_assert(std::is_same_v<V, Element>,
                          "Program::set(handle, value): the value's C++ type does not match the uniform's GLSL type");
            if (compiledIn(uniform.name)) set(uniform.name, value);
        } else {
            static_assert(std::is_convertible_v<const V&, std::span<const Element>>,
                          "Program::set(handle, values): an array uniform takes a range of its element type");
            if (compiledIn(uniform.name)) set(uniform.name, std::span<const Element>(value));
        }
    }

    // Active uniforms never set since link, each by name: samplers (left at unit 0 on
    // purpose) and uniforms with an initialiser in GLSL are left out.
    std::vector<std::string> unsetUniforms() const;
    // Warns once per program and uniform about unsetUniforms(), when the unset-uniform
    // check is on (setUnsetUniformCheck; GpuMesh::draw calls this before the first draw).
    void reportUnsetUniforms() const;
    // Whether reportUnsetUniforms() warns; new Programs take setDefaultUnsetUniformCheck's value.
    void setUnsetUniformCheck(bool on) { checkUnset_ = on; }
    // Handles set() was given whose uniform this variant does not have, each once, in order.
    const std::vector<std::string>& compiledOutUniforms() const { return compiledOut_; }

    // Whether this program runs a variant of `shader` of a generated catalogue. Programs
    // composed or built from raw sources know no shader: false for every shader, and
    // set(handle) takes any shader's handles (their names are still checked).
    bool builtFrom(const catalog::Shader& shader) const;
    // Handles of another shader set() was given, as "<shader>::<uniform>", each once, in order.
    const std::vector<std::string>& foreignHandleReports() const { return foreignReports_; }

    // Replaces where this program's warnings go (empty function: the default handler).
    void setWarningHandler(WarningHandler handler);
    // Names set() was called with that the program does not have, each once, in order.
    const std::vector<std::string>& unknownUniformReports() const { return unknownReports_; }
    // Names set() was called with using a C++ type that does not fit, each once.
    const std::vector<std::string>& typeMismatchReports() const { return mismatchReports_; }

  private:
    struct UniformSlot {
        int location = -1;
        std::uint32_t glType = 0;  // 0: unknown, no type check
        int elements = 1;          // elements from this slot to the end of its array
    };
    using SetterKind = detail::UniformSetterKind;

    void build(ProgramSources sources);
    void buildUniformTable(const std::optional<std::vector<UniformDecl>>& reflected);
    void addUniform(const std::string& name, std::uint32_t glType, int arraySize);
    const UniformSlot* slotFor(std::string_view name);
    const UniformSlot* prepare(std::string_view name, SetterKind kind, std::size_t count);
    void warn(const std::string& message) const;
    bool compiledIn(std::string_view name);                                       // false: recorded in compiledOut_
    bool takesHandleOf(const catalog::Shader& shader, std::string_view uniform);  // false: reported once
    std::vector<std::string> uniformNames() const;                                // declared_, for "did you mean"
    void startUnsetCheck(const std::vector<StageText>& stages);                   // at link: initialisers, the switch

    struct DeclaredUniform {
        std::string name;  // without "[0]"
        std::uint32_t glType = 0;
    };

    ProgramObject program_;
    std::string label_;
    std::vector<AttributeBinding> activeAttributes_;
    std::map<std::string, UniformSlot, std::less<>> uniforms_;
    std::set<std::string, std::less<>> reported_;
    std::vector<std::string> unknownReports_;
    std::vector<std::string> mismatchReports_;
    WarningHandler warningHandler_;
    std::vector<DeclaredUniform> declared_;           // active, as reflected or reported by the driver
    std::set<std::string, std::less<>> initialised_;  // declared with an initialiser in GLSL
    std::set<std::string, std::less<>> setSinceLink_;
    std::vector<std::string> compiledOut_;
    std::vector<std::string> foreignReports_;
    const catalog::Variant* variant_ = nullptr;  // what it was built from; null: no catalogue shader
    bool checkUnset_ = false;
    mutable std::set<std::string, std::less<>> unsetReported_;
};

// The unset-uniform check of new Programs (Program::reportUnsetUniforms): on by default in
// debug builds, off in release builds; the viewer turns it on.
void setDefaultUnsetUniformCheck(bool on);

// A Program seen as built from the shader tagged `Shader` (a generated header's
// `<namespace>::<shader>::Shader`): set() takes only that shader's handles, so another
// shader's uniform is a compile error. A view: `program` must outlive it.
template <class Shader>
class ProgramOf {
  public:
    explicit ProgramOf(Program& program) : program_(&program) {}
    Program& program() const { return *program_; }

    template <catalog::GlslType T, std::size_t N, class V>
    void set(const catalog::UniformHandle<T, N, Shader>& uniform, const V& value) const {
        program_->set(uniform, value);
    }
    template <catalog::GlslType T, std::size_t N, class Other, class V>
    void set(const catalog::UniformHandle<T, N, Other>&, const V&) const {
        static_assert(detail::kAlwaysFalse<Other>, "ProgramOf<Shader>::set: the handle belongs to another shader");
    }

  private:
    Program* program_;
};

}  // namespace prism::gl
