// Types of the shader catalogue that prism-shaderc generates: the contract between
// the build-time tool and the runtime.
//
// A generated header (see docs/shaderc.md) declares, in the namespace it was given:
//
//     enum class ShaderId : std::uint32_t { unicolor, phong, ..., };
//     enum class ModuleId : std::uint32_t { lights, transforms, ..., };
//     extern const prism::catalog::Catalog kCatalog;   // defined in the generated .cpp
//     const prism::catalog::Shader& shaderInfo(ShaderId);
//     const prism::catalog::Module& moduleInfo(ModuleId);
//
// and its generated .cpp defines kCatalog: constant-initialised data pointing into string
// literals and arrays of static storage, so it costs nothing at start-up. A stage's
// `chunks` are pieces shared with other stages (each text is stored once); joinChunks()
// assembles them.
//
// Usage (snippet: examples/snippets/catalog_shader_catalog.cpp):
//
//     #include "prism/shaders.hpp"  // generated
//     const auto& s = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
//     // A misspelled axis or value throws VariantLookupError naming it and the known ones;
//     // nullptr means known values whose combination was not generated (VARIANTS).
//     const auto* v = prism::catalog::findVariant(s, {{"BLINN", "1"}});
//     if (v == nullptr) return 1;
//     std::string vert = prism::catalog::joinChunks(v->stages[0].chunks);
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/catalog/did_you_mean.hpp"

namespace prism::catalog {

// The stage kinds, named by their file extensions (glslang's). The enumerators' values are
// stored in generated catalogues: new kinds go at the end; pipelineOrder() gives the order a
// program's stages run in. Mesh, task and the ray-tracing kinds exist for the Vulkan client
// only (prism-shaderc --client vulkan).
enum class Stage : std::uint8_t {
    Vertex,
    Geometry,
    Fragment,
    Compute,
    TessControl,
    TessEvaluation,
    Mesh,
    Task,
    RayGen,
    Intersect,
    AnyHit,
    ClosestHit,
    Miss,
    Callable,
};

// The stage file's extension without the dot, as glslang names it.
constexpr std::string_view stageName(Stage s) {
    switch (s) {
        case Stage::Vertex: return "vert";
        case Stage::Geometry: return "geom";
        case Stage::Fragment: return "frag";
        case Stage::Compute: return "comp";
        case Stage::TessControl: return "tesc";
        case Stage::TessEvaluation: return "tese";
        case Stage::Mesh: return "mesh";
        case Stage::Task: return "task";
        case Stage::RayGen: return "rgen";
        case Stage::Intersect: return "rint";
        case Stage::AnyHit: return "rahit";
        case Stage::ClosestHit: return "rchit";
        case Stage::Miss: return "rmiss";
        case Stage::Callable: return "rcall";
    }
    return "?";
}

// The stage's place in a program: vert, tesc, tese, geom (or task, mesh), frag; compute
// on its own; the ray-tracing stages in their enumerators' order.
constexpr int pipelineOrder(Stage s) {
    switch (s) {
        case Stage::Vertex: return 0;
        case Stage::TessControl: return 1;
        case Stage::TessEvaluation: return 2;
        case Stage::Geometry: return 3;
        case Stage::Task: return 4;
        case Stage::Mesh: return 5;
        case Stage::Fragment: return 6;
        case Stage::Compute: return 7;
        default: return 8 + static_cast<int>(s);  // the ray-tracing kinds
    }
}

// Ray-tracing stages are validated one by one (as glslc does): no stage interface links them.
constexpr bool isRayTracingStage(Stage s) {
    return s >= Stage::RayGen && s <= Stage::Callable;
}

// One row of a line table: `#line L <number>` in an embedded source means line L
// of `path`. Source number 0 is always the stage file itself.
// `path` is relative to prism-shaderc's --base-dir, or, for a file found through an -I
// directory outside it (an installed Prism's modules), to that directory: `searchDir`
// says which (0: the base dir; k: the k-th -I directory, from 1). Paths so stay free of
// where the checkout lies; hot reload (prism/render/shader_watcher.hpp) joins them back.
struct SourceFile {
    std::uint32_t number;
    std::string_view path;
    std::uint32_t searchDir = 0;
};

// One stage of one variant: driver-safe GLSL (version on line 1, integer #line only)
// as pieces of at most 16 KB (MSVC's string-literal limit) that other stages share: the
// #version/#define block, #line lines, module bodies, the stage's body. Concatenate them.
// A Vulkan-client catalogue (prism-shaderc --client vulkan) and the spirv target (--target
// spirv, Vulkan 1.1) also store the stage's SPIR-V words (each distinct module once);
// otherwise `spirv` is empty.
struct StageSource {
    Stage stage;
    std::span<const std::string_view> chunks;
    std::span<const SourceFile> files;
    std::span<const std::uint32_t> spirv = {};
};

// The array size that means unbounded: a descriptor array declared `textures[]`, or a
// storage block's last member `T x[]` (a runtime array). A non-array has size 1, so 0 is
// never a real size.
inline constexpr std::uint32_t kUnboundedArray = 0;

// A vertex attribute. `location` comes from the binding contract, so the runtime binds it
// with glBindAttribLocation before linking; in a Vulkan-client catalogue it is the
// shader's own `layout(location = N)`. OpenGL catalogues list the active ones; the SPIR-V's
// (`spirvInputs`, a Vulkan client's `attributes`) every declared one, `used` saying whether
// the vertex stage statically reads it.
struct Attribute {
    std::string_view name;
    std::uint32_t glType;  // GL_FLOAT_VEC3 etc.
    std::int32_t location;
    bool used = true;
};

// An active uniform; arraySize is 1 for non-arrays.
struct Uniform {
    std::string_view name;
    std::uint32_t glType;
    std::int32_t arraySize;
};

// What a Vulkan descriptor binding holds (VkDescriptorType's names).
enum class ResourceKind : std::uint8_t {
    UniformBuffer,
    StorageBuffer,
    CombinedImageSampler,
    SampledImage,
    StorageImage,
    Sampler,
    UniformTexelBuffer,
    StorageTexelBuffer,
    InputAttachment,
    AccelerationStructure,
};

// The enumerator's own spelling ("UniformBuffer"), for messages and generated code.
constexpr std::string_view resourceKindName(ResourceKind k) {
    switch (k) {
        case ResourceKind::UniformBuffer: return "UniformBuffer";
        case ResourceKind::StorageBuffer: return "StorageBuffer";
        case ResourceKind::CombinedImageSampler: return "CombinedImageSampler";
        case ResourceKind::SampledImage: return "SampledImage";
        case ResourceKind::StorageImage: return "StorageImage";
        case ResourceKind::Sampler: return "Sampler";
        case ResourceKind::UniformTexelBuffer: return "UniformTexelBuffer";
        case ResourceKind::StorageTexelBuffer: return "StorageTexelBuffer";
        case ResourceKind::InputAttachment: return "InputAttachment";
        case ResourceKind::AccelerationStructure: return "AccelerationStructure";
    }
    return "?";
}

// A member of a buffer block: `offset` in bytes from the block's start, as the SPIR-V lays
// it out (std140, std430 or scalar). Nested structs are flattened (`Block.light.color`,
// `Block.lights[1].color`). `size` is the bytes of the whole member (every element; 0 for
// a runtime array), `arrayStride` the bytes from one element to the next (0: no array).
// A `buffer_reference` member is an 8-byte device address (`deviceAddress`, glType
// GL_UNSIGNED_INT64_ARB), never the pointee's members.
struct BlockMember {
    std::string_view name;
    std::uint32_t glType;
    std::uint32_t offset;
    std::int32_t arraySize;  // 1 for non-arrays; kUnboundedArray for a runtime array
    std::uint32_t size = 0;
    std::uint32_t arrayStride = 0;
    bool deviceAddress = false;
};

// One descriptor of the SPIR-V of a variant, every declared one (a descriptor-set layout
// needs the unused ones too; `used` says whether some stage statically uses it). `size` is
// a buffer block's size in bytes as its layout gives it (0 for images and samplers): for a
// storage block ending in a runtime array `T x[]`, the fixed part before it, and
// `runtimeStride` the bytes of one T (so n elements take size + n * runtimeStride).
// `arraySize` is 1 for non-arrays, kUnboundedArray for `textures[]`. A buffer block lists
// its members, so an application fills it without another reflection library; the spirv
// target's loose uniforms are those of `gl_DefaultUniformBlock` (glslang's relaxed Vulkan rules).
struct Resource {
    std::string_view name;
    std::uint32_t set;
    std::uint32_t binding;
    ResourceKind kind;
    std::uint32_t size;
    std::uint32_t arraySize;
    std::span<const BlockMember> members = {};  // buffer blocks: by offset
    std::uint32_t runtimeStride = 0;
    bool used = true;
};

// A member of a variant's push-constant block (flattened as BlockMember), at `offset` bytes,
// `size` bytes long (every element). A `buffer_reference` member is an 8-byte device address
// (`deviceAddress`, glType GL_UNSIGNED_INT64_ARB). The push-constant range a pipeline layout
// needs runs from the first member's offset to the largest offset + size.
struct PushConstant {
    std::string_view name;
    std::uint32_t glType;
    std::uint32_t offset;
    std::uint32_t size;
    std::int32_t arraySize = 1;
    std::uint32_t arrayStride = 0;
    bool deviceAddress = false;
};

// A specialisation constant (`layout(constant_id = N) const T name = default;`): its
// default as the 32 bits of the SPIR-V literal (a float's bits for float, 0/1 for bool).
struct SpecConstant {
    std::string_view name;
    std::uint32_t id;
    std::uint32_t glType;
    std::uint32_t defaultBits;
};

struct Define {
    std::string_view name;
    std::string_view value;
};

// One axis declared with `#pragma prism variant NAME [values...]`.
struct VariantAxis {
    std::string_view name;
    std::span<const std::string_view> values;
};

// One validated combination of axis values. `stages` is the gl target (desktop GLSL, or the
// Vulkan client's GLSL); each StageSource's `spirv` and the fields from `resources` on are
// the SPIR-V's (the Vulkan client's, or the spirv target's), `es300Stages` the es300
// target's: empty when the catalogue was built without them (prism-shaderc --target,
// docs/targets.md) or the shader opted out.
struct Variant {
    std::string_view name;                // e.g. "FOG=1,DIRECTIONAL_LIGHTS=4" or "default"
    std::span<const Define> defines;      // one per axis, in axis order
    std::span<const StageSource> stages;  // in pipeline order
    std::span<const Attribute> attributes;
    std::span<const Uniform> uniforms;
    // Descriptors, push constants and specialisation constants of the SPIR-V in `stages`:
    // the Vulkan client's, or the spirv target's (its loose uniforms in one block per stage).
    std::span<const Resource> resources = {};          // by set, then binding
    std::span<const PushConstant> pushConstants = {};  // Vulkan client: by offset
    std::span<const SpecConstant> specConstants = {};  // Vulkan client: by id
    std::span<const StageSource> es300Stages = {};     // es300 target: GLSL ES 3.00, line tables as `stages`
    // The vertex inputs at the locations the SPIR-V uses: the spirv target's, assigned by
    // glslang; in a Vulkan-client catalogue the shader's own, as in `attributes`.
    std::span<const Attribute> spirvInputs = {};
};

struct Shader {
    std::string_view name;
    std::span<const VariantAxis> axes;
    std::span<const Variant> variants;
    std::span<const std::uint32_t> modules;  // ModuleId values of every module any variant uses
};

// A reusable GLSL module (what SHADER_MODULE is in the FUDGE shader thesis §7.1). `chunks` hold the module's own
// text with its #include and #pragma once lines blanked (line numbers kept; its #version
// line stays, so run-time composition holds it to the build step's one-version rule);
// `dependencies` are its direct includes (ModuleId values) in include order. `path` and
// `searchDir` are as in SourceFile.
struct Module {
    std::string_view name;
    std::string_view path;
    std::string_view description;
    std::span<const std::string_view> chunks;
    std::span<const std::uint32_t> dependencies;
    std::uint32_t searchDir = 0;
};

// A whole generated catalogue.
struct Catalog {
    std::span<const Shader> shaders;
    std::span<const Module> modules;
    std::span<const Attribute> contractAttributes;  // everything the runtime supplies
    std::span<const Uniform> contractUniforms;
    std::string_view versionDirective;  // e.g. "#version 330 core"
    // The --contract files, in order, with paths as in SourceFile (relative to the base dir
    // or their -I directory; `number` is the position): what run-time contract errors name.
    // Empty: Prism's built-in contract (no --contract).
    std::span<const SourceFile> contractFiles = {};
    std::string_view targetEnv = {};  // "vulkan1.2" etc. for a Vulkan-client catalogue; "" for OpenGL
};

inline std::string joinChunks(std::span<const std::string_view> chunks) {
    std::string out;
    std::size_t n = 0;
    for (auto c : chunks) n += c.size();
    out.reserve(n);
    for (auto c : chunks) out.append(c);
    return out;
}

constexpr const Shader* findShader(const Catalog& c, std::string_view name) {
    for (const auto& s : c.shaders)
        if (s.name == name) return &s;
    return nullptr;
}

constexpr const Module* findModule(const Catalog& c, std::string_view name) {
    for (const auto& m : c.modules)
        if (m.name == name) return &m;
    return nullptr;
}

// The location the binding contract gives attribute `name` (e.g. "a_position"); throws
// std::out_of_range naming the attribute when the contract has no such attribute.
inline std::int32_t attributeLocation(std::span<const Attribute> contract, std::string_view name) {
    std::vector<std::string> names;
    for (const auto& a : contract) {
        if (a.name == name) return a.location;
        names.emplace_back(a.name);
    }
    throw std::out_of_range("the binding contract has no attribute '" + std::string(name) + "'" +
                            didYouMean(name, names) + " (its attributes: " + nameList(names) +
                            "); declare it in the contract JSON (modules/contract.json) or use a contract name");
}
inline std::int32_t attributeLocation(const Catalog& c, std::string_view name) {
    return attributeLocation(c.contractAttributes, name);
}

namespace detail {
inline std::string_view wantedName(const Define& d) {
    return d.name;
}
inline std::string_view wantedValue(const Define& d) {
    return d.value;
}
template <class Name, class Value>
std::string_view wantedName(const std::pair<Name, Value>& p) {
    return p.first;
}
template <class Name, class Value>
std::string_view wantedValue(const std::pair<Name, Value>& p) {
    return p.second;
}
}  // namespace detail

// Thrown by findVariant for a name that is no axis of the shader, or a value its axis
// never declared; the message names it, with "did you mean", and lists the known ones.
class VariantLookupError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

namespace detail {
inline std::vector<std::string> namesOf(std::span<const VariantAxis> axes) {
    std::vector<std::string> out;
    for (const auto& ax : axes) out.emplace_back(ax.name);
    return out;
}
inline std::vector<std::string> namesOf(std::span<const std::string_view> values) {
    return {values.begin(), values.end()};
}

// Throws VariantLookupError unless `name` is an axis of `s` and `value` one of its values.
inline void requireAxisValue(const Shader& s, std::string_view name, std::string_view value) {
    for (const auto& ax : s.axes) {
        if (ax.name != name) continue;
        for (const auto& v : ax.values)
            if (v == value) return;
        const auto values = namesOf(ax.values);
        throw VariantLookupError("variant axis '" + std::string(name) + "' of shader '" + std::string(s.name) +
                                 "' has no value '" + std::string(value) + "'" + didYouMean(value, values) +
                                 "; its values: " + nameList(values));
    }
    const auto axes = namesOf(s.axes);
    throw VariantLookupError("shader '" + std::string(s.name) + "' has no variant axis '" + std::string(name) + "'" +
                             didYouMean(name, axes) + "; its axes: " + nameList(axes));
}
}  // namespace detail

// The variant whose axis values equal `wanted` (Defines, or pairs of strings); axes not
// named in `wanted` take their first declared value. A name in `wanted` that is no axis,
// or a value its axis never declared, throws VariantLookupError. Returns nullptr only
// for declared values whose combination was not generated (prism_add_shaders VARIANTS).
template <class Range>
const Variant* findVariant(const Shader& s, const Range& wanted) {
    for (const auto& w : wanted) detail::requireAxisValue(s, detail::wantedName(w), detail::wantedValue(w));
    for (const auto& v : s.variants) {
        bool match = true;
        for (std::size_t a = 0; a < s.axes.size() && match; ++a) {
            std::string_view want = s.axes[a].values.empty() ? std::string_view{} : s.axes[a].values[0];
            for (const auto& w : wanted)
                if (detail::wantedName(w) == s.axes[a].name) want = detail::wantedValue(w);
            match = v.defines.size() > a && v.defines[a].value == want;
        }
        if (match) return &v;
    }
    return nullptr;
}

inline const Variant* findVariant(const Shader& s, std::initializer_list<Define> wanted) {
    return findVariant<std::initializer_list<Define>>(s, wanted);
}

constexpr const SourceFile* findSourceFile(const StageSource& s, std::uint32_t number) {
    for (const auto& f : s.files)
        if (f.number == number) return &f;
    return nullptr;
}

}  // namespace prism::catalog
