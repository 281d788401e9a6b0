// A program's layout from its stages' SPIR-V, through SPIRV-Cross (see vulkan_reflection.hpp).
#include "vulkan_reflection.hpp"

#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "contract.hpp"
#include "spirv_words.hpp"

namespace prism::shaderc {
namespace {

using catalog::ResourceKind;

// SPIRV-Cross's C API: a context owns every handle made from it.
struct SpvcContext {
    spvc_context context = nullptr;
    SpvcContext() { spvc_context_create(&context); }
    ~SpvcContext() {
        if (context) spvc_context_destroy(context);
    }
    SpvcContext(const SpvcContext&) = delete;
    SpvcContext& operator=(const SpvcContext&) = delete;
};

// The GLSL spelling of a scalar, vector or matrix type, as `spirv-cross --reflect` prints it.
std::string glslTypeName(spvc_type t) {
    static const std::map<spvc_basetype, std::pair<const char*, const char*>> names = {
        {SPVC_BASETYPE_BOOLEAN, {"bool", "b"}},      {SPVC_BASETYPE_INT8, {"int8_t", "i8"}},
        {SPVC_BASETYPE_UINT8, {"uint8_t", "u8"}},    {SPVC_BASETYPE_INT16, {"int16_t", "i16"}},
        {SPVC_BASETYPE_UINT16, {"uint16_t", "u16"}}, {SPVC_BASETYPE_INT32, {"int", "i"}},
        {SPVC_BASETYPE_UINT32, {"uint", "u"}},       {SPVC_BASETYPE_INT64, {"int64_t", "i64"}},
        {SPVC_BASETYPE_UINT64, {"uint64_t", "u64"}}, {SPVC_BASETYPE_FP16, {"float16_t", "f16"}},
        {SPVC_BASETYPE_FP32, {"float", ""}},         {SPVC_BASETYPE_FP64, {"double", "d"}},
    };
    const auto it = names.find(spvc_type_get_basetype(t));
    if (it == names.end()) return "";
    const unsigned rows = spvc_type_get_vector_size(t), columns = spvc_type_get_columns(t);
    const std::string prefix = it->second.second;
    if (columns > 1)
        return prefix + "mat" + std::to_string(columns) + (rows == columns ? "" : "x" + std::to_string(rows));
    return rows > 1 ? prefix + "vec" + std::to_string(rows) : it->second.first;
}

// The value of every 32-bit integer constant of a module at its specialisation constants'
// defaults: OpConstant, OpSpecConstant and the integer arithmetic of OpSpecConstantOp (an array
// sized `MAX_LOD + 1`), which SPIRV-Cross's C API gives no value for. SPIR-V defines each id
// before its use, so one pass in order evaluates them all.
using ConstantValues = std::map<SpvId, std::uint32_t>;
// A division of the constants that traps (by zero, or INT_MIN / -1) is an error here, before
// SPIRV-Cross, which evaluates it too, divides.
ConstantValues constantValues(std::span<const std::uint32_t> words) {
    ConstantValues v;
    forEachInstruction(words, [&](std::uint32_t op, std::span<const std::uint32_t> a, std::size_t) {
        if ((op == SpvOpConstant || op == SpvOpSpecConstant) && a.size() == 3) v[a[1]] = a[2];
        if (op == SpvOpSpecConstantOp && a.size() == 5 && v.count(a[3]) && v.count(a[4])) {
            const std::uint32_t x = v[a[3]], y = v[a[4]];
            const bool division =
                a[2] == SpvOpUDiv || a[2] == SpvOpSDiv || a[2] == SpvOpUMod || a[2] == SpvOpSRem || a[2] == SpvOpSMod;
            const bool signedDivision = a[2] == SpvOpSDiv || a[2] == SpvOpSRem || a[2] == SpvOpSMod;
            if (division && (y == 0 || (signedDivision && x == 0x80000000u && y == 0xFFFFFFFFu)))
                throw std::runtime_error(
                    "a constant expression divides by zero or overflows (INT_MIN / -1) at the specialisation "
                    "constants' defaults; give them defaults that keep it defined");
            switch (a[2]) {
                case SpvOpIAdd: v[a[1]] = x + y; break;
                case SpvOpISub: v[a[1]] = x - y; break;
                case SpvOpIMul: v[a[1]] = x * y; break;
                case SpvOpUDiv:
                    if (y != 0) v[a[1]] = x / y;
                    break;
                case SpvOpSDiv:
                    if (y != 0)
                        v[a[1]] =
                            static_cast<std::uint32_t>(static_cast<std::int32_t>(x) / static_cast<std::int32_t>(y));
                    break;
                default: break;
            }
        }
        return true;
    });
    return v;
}

// An array type's dimensions, outermost first; a size given by a constant (a specialisation
// constant's default, or arithmetic on one) at its value.
std::vector<std::uint32_t> arrayDims(spvc_type t, const ConstantValues& constants) {
    std::vector<std::uint32_t> dims;
    for (unsigned d = spvc_type_get_num_array_dimensions(t); d-- > 0;) {
        const SpvId size = spvc_type_get_array_dimension(t, d);
        if (spvc_type_array_dimension_is_literal(t, d)) {
            dims.push_back(size);
            continue;
        }
        const auto value = constants.find(size);
        if (value == constants.end())
            throw std::runtime_error("an array is sized by constant %" + std::to_string(size) +
                                     ", whose value Prism cannot evaluate");
        dims.push_back(value->second);
    }
    return dims;
}

// Elements of all dimensions together; kUnboundedArray when one is unbounded.
std::uint32_t elementCount(const std::vector<std::uint32_t>& dims) {
    std::uint32_t n = 1;
    for (auto d : dims) n *= d;
    return n;
}

constexpr std::uint32_t kGlUnsignedInt64 = 0x140F;  // GL_UNSIGNED_INT64_ARB: a device address's host type

bool isDeviceAddress(spvc_type t) {
    return spvc_type_get_storage_class(t) == SpvStorageClassPhysicalStorageBuffer;
}

// The leaves of struct `index` of `layout`, at `base` bytes, named from `prefix`.
void flatten(const ReflectedBlockLayout& layout, int index, const std::string& prefix, std::uint32_t base,
             std::vector<ReflectedBlockMember>& out) {
    for (const auto& m : layout[index].members) {
        const std::uint32_t count = elementCount(m.arrayDims);
        if (m.structIndex < 0) {
            out.push_back({prefix + m.name, m.deviceAddress ? kGlUnsignedInt64 : glTypeOf(m.glslType), base + m.offset,
                           static_cast<int>(count), m.size, m.arrayStride, m.deviceAddress, m.glslType});
            continue;
        }
        if (m.arrayDims.empty()) {
            flatten(layout, m.structIndex, prefix + m.name + ".", base + m.offset, out);
            continue;
        }
        // An array of structs, element by element (a runtime array: its first element).
        for (std::uint32_t e = 0; e < std::max(count, 1u); ++e)
            flatten(layout, m.structIndex, prefix + m.name + "[" + std::to_string(e) + "].",
                    base + m.offset + e * m.arrayStride, out);
    }
}

// A stage's module, parsed once, with what its entry point statically uses.
class StageReflector {
  public:
    StageReflector(std::span<const std::uint32_t> words, ProgramReflection& r)
        : constants_(constantValues(words)), r_(r) {
        spvc_parsed_ir ir = nullptr;
        if (spvc_context_parse_spirv(ctx_.context, words.data(), words.size(), &ir) != SPVC_SUCCESS ||
            spvc_context_create_compiler(ctx_.context, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                         &compiler_) != SPVC_SUCCESS)
            throw std::runtime_error(std::string("SPIRV-Cross cannot read the SPIR-V: ") +
                                     spvc_context_get_last_error_string(ctx_.context));
        spvc_set active = nullptr;
        spvc_compiler_get_active_interface_variables(compiler_, &active);
        spvc_compiler_create_shader_resources(compiler_, &all_);
        spvc_compiler_create_shader_resources_for_active_variables(compiler_, &active_, active);
    }

    void reflect(bool vertexStage) {
        if (vertexStage)
            for (const auto& in : list(all_, SPVC_RESOURCE_TYPE_STAGE_INPUT)) addInput(in);
        for (const auto& [type, kind] : kDescriptorLists)
            for (const auto& res : list(all_, type)) addDescriptor(res, type, kind);
        for (const auto& res : list(all_, SPVC_RESOURCE_TYPE_PUSH_CONSTANT)) addPushConstants(res);
    }

  private:
    static constexpr std::pair<spvc_resource_type, ResourceKind> kDescriptorLists[] = {
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, ResourceKind::UniformBuffer},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, ResourceKind::StorageBuffer},
        {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, ResourceKind::CombinedImageSampler},
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, ResourceKind::SampledImage},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, ResourceKind::StorageImage},
        {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, ResourceKind::Sampler},
        {SPVC_RESOURCE_TYPE_SUBPASS_INPUT, ResourceKind::InputAttachment},
        {SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE, ResourceKind::AccelerationStructure},
    };

    static std::span<const spvc_reflected_resource> list(spvc_resources resources, spvc_resource_type type) {
        const spvc_reflected_resource* items = nullptr;
        std::size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, type, &items, &count);
        return {items, count};
    }

    bool used(const spvc_reflected_resource& res, spvc_resource_type type) const {
        const auto active = list(active_, type);
        return std::any_of(active.begin(), active.end(), [&](const auto& a) { return a.id == res.id; });
    }

    spvc_type type(spvc_type_id id) const { return spvc_compiler_get_type_handle(compiler_, id); }

    void addInput(const spvc_reflected_resource& in) {
        const std::string name = in.name;
        if (name.rfind("gl_", 0) == 0 || !spvc_compiler_has_decoration(compiler_, in.id, SpvDecorationLocation)) return;
        const std::string glslType = glslTypeName(type(in.type_id));
        r_.attributes.push_back(
            {name, glTypeOf(glslType),
             static_cast<int>(spvc_compiler_get_decoration(compiler_, in.id, SpvDecorationLocation)),
             used(in, SPVC_RESOURCE_TYPE_STAGE_INPUT), glslType});
    }

    // The Vulkan descriptor kind: texel buffers are images of dimension Buffer.
    static ResourceKind kindOf(spvc_type t, ResourceKind listed) {
        if (spvc_type_get_basetype(t) != SPVC_BASETYPE_IMAGE &&
            spvc_type_get_basetype(t) != SPVC_BASETYPE_SAMPLED_IMAGE)
            return listed;
        if (spvc_type_get_image_dimension(t) != SpvDimBuffer) return listed;
        return listed == ResourceKind::StorageImage ? ResourceKind::StorageTexelBuffer
                                                    : ResourceKind::UniformTexelBuffer;
    }

    void addDescriptor(const spvc_reflected_resource& res, spvc_resource_type listType, ResourceKind listed) {
        const spvc_type t = type(res.type_id);
        ReflectedResource x;
        x.name = res.name;
        x.set = spvc_compiler_get_decoration(compiler_, res.id, SpvDecorationDescriptorSet);
        x.binding = spvc_compiler_get_decoration(compiler_, res.id, SpvDecorationBinding);
        x.kind = kindOf(t, listed);
        x.arraySize = elementCount(arrayDims(t, constants_));
        x.used = used(res, listType);
        if (listed == ResourceKind::UniformBuffer || listed == ResourceKind::StorageBuffer) {
            x.layout = layoutOf(type(res.base_type_id));
            x.size = x.layout[0].size;
            const auto& members = x.layout[0].members;
            if (!members.empty() && !members.back().arrayDims.empty() &&
                members.back().arrayDims[0] == catalog::kUnboundedArray)
                x.runtimeStride = members.back().arrayStride;
            flatten(x.layout, 0, blockPrefix(res), 0, x.members);
        }
        mergeResource(std::move(x));
    }

    // glslang's member names: `Block.member` for a block with an instance name, `member` without.
    std::string blockPrefix(const spvc_reflected_resource& res) const {
        const std::string instance = spvc_compiler_get_name(compiler_, res.id);
        return instance.empty() ? "" : std::string(spvc_compiler_get_name(compiler_, res.base_type_id)) + ".";
    }

    void addPushConstants(const spvc_reflected_resource& res) {
        auto layout = layoutOf(type(res.base_type_id));
        std::vector<ReflectedBlockMember> members;
        flatten(layout, 0, blockPrefix(res), 0, members);
        for (const auto& m : members) {
            // Stages name one push-constant block differently: the same bytes are one member,
            // named by the first stage that declares them.
            const bool known = std::any_of(r_.pushConstants.begin(), r_.pushConstants.end(),
                                           [&](const auto& p) { return p.offset == m.offset && p.glType == m.glType; });
            if (!known)
                r_.pushConstants.push_back(
                    {m.name, m.glType, m.offset, m.size, m.arraySize, m.arrayStride, m.deviceAddress, m.glslType});
        }
        if (r_.pushConstantLayout.empty() || layout[0].size > r_.pushConstantLayout[0].size)
            r_.pushConstantLayout = std::move(layout);
    }

    // One resource per set and binding: a later stage's adds its use and the members it has more.
    // Declarations that alias one binding under different names (one chosen by a specialisation
    // constant) give the binding the first name in alphabetical order, with its members.
    void mergeResource(ReflectedResource x) {
        for (auto& known : r_.resources) {
            if (known.set != x.set || known.binding != x.binding) continue;
            known.used = known.used || x.used;
            if (x.name != known.name) {
                if (x.name < known.name) {
                    x.used = known.used;
                    known = std::move(x);
                }
                return;
            }
            for (auto& m : x.members)
                if (std::none_of(known.members.begin(), known.members.end(),
                                 [&](const auto& k) { return k.name == m.name; }))
                    known.members.push_back(std::move(m));
            if (x.size > known.size) {
                known.size = x.size;
                known.layout = std::move(x.layout);
            }
            return;
        }
        r_.resources.push_back(std::move(x));
    }

    ReflectedBlockLayout layoutOf(spvc_type block) const {
        ReflectedBlockLayout layout;
        addStruct(block, layout);
        return layout;
    }

    // Appends struct type `t` (and the struct types it holds) to `layout`; returns its index.
    int addStruct(spvc_type t, ReflectedBlockLayout& layout) const {
        const spvc_type_id self = spvc_type_get_base_type_id(t);
        const int index = static_cast<int>(layout.size());
        layout.push_back({spvc_compiler_get_name(compiler_, self), 0, {}});
        std::size_t size = 0;
        spvc_compiler_get_declared_struct_size(compiler_, t, &size);
        layout[index].size = static_cast<std::uint32_t>(size);
        for (unsigned i = 0; i < spvc_type_get_num_member_types(t); ++i) {
            auto m = memberOf(t, self, i);
            const spvc_type mt = type(spvc_type_get_member_type(t, i));
            if (!m.deviceAddress && spvc_type_get_basetype(mt) == SPVC_BASETYPE_STRUCT) {
                m.structIndex = addStruct(mt, layout);
                m.glslType = layout[m.structIndex].name;
            }
            layout[index].members.push_back(std::move(m));
        }
        return index;
    }

    ReflectedStructMember memberOf(spvc_type t, spvc_type_id self, unsigned i) const {
        const spvc_type mt = type(spvc_type_get_member_type(t, i));
        ReflectedStructMember m;
        m.name = spvc_compiler_get_member_name(compiler_, self, i);
        m.deviceAddress = isDeviceAddress(mt);
        m.glslType = m.deviceAddress ? "uint64_t" : glslTypeName(mt);
        m.arrayDims = arrayDims(mt, constants_);
        spvc_compiler_type_struct_member_offset(compiler_, t, i, &m.offset);
        if (!m.arrayDims.empty()) spvc_compiler_type_struct_member_array_stride(compiler_, t, i, &m.arrayStride);
        if (spvc_type_get_columns(mt) > 1 && !m.deviceAddress)
            spvc_compiler_type_struct_member_matrix_stride(compiler_, t, i, &m.matrixStride);
        m.rowMajor = spvc_compiler_has_member_decoration(compiler_, self, i, SpvDecorationRowMajor);
        std::size_t size = 0;
        if (m.deviceAddress)
            size = 8 * elementCount(m.arrayDims);
        else if (elementCount(m.arrayDims) != catalog::kUnboundedArray)
            spvc_compiler_get_declared_struct_member_size(compiler_, t, i, &size);
        m.size = static_cast<std::uint32_t>(size);
        return m;
    }

    ConstantValues constants_;
    SpvcContext ctx_;
    spvc_compiler compiler_ = nullptr;
    spvc_resources all_ = nullptr, active_ = nullptr;
    ProgramReflection& r_;
};

}  // namespace

void reflectSpirv(ProgramReflection& r) {
    r.attributes.clear();
    r.resources.clear();
    r.pushConstants.clear();
    r.pushConstantLayout.clear();
    r.specConstants.clear();
    for (const auto& stage : r.spirv) {
        StageReflector(stage.words, r).reflect(stage.stage == catalog::Stage::Vertex);
        addSpecConstants(r, stage.words);
    }
    for (auto& x : r.resources)
        std::sort(x.members.begin(), x.members.end(),
                  [](const auto& a, const auto& b) { return std::tie(a.offset, a.name) < std::tie(b.offset, b.name); });
    std::sort(r.attributes.begin(), r.attributes.end(), [](const auto& a, const auto& b) {
        return a.location != b.location ? a.location < b.location : a.name < b.name;
    });
    std::sort(r.resources.begin(), r.resources.end(), [](const auto& a, const auto& b) {
        return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    });
    std::sort(r.pushConstants.begin(), r.pushConstants.end(),
              [](const auto& a, const auto& b) { return std::tie(a.offset, a.name) < std::tie(b.offset, b.name); });
}

namespace {

// SPIR-V opcodes and decorations read here (SPIR-V specification, section 3).
constexpr std::uint32_t kOpName = 5, kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpSpecConstantTrue = 48,
                        kOpSpecConstantFalse = 49, kOpSpecConstant = 50, kOpDecorate = 71, kDecorationSpecId = 1;
constexpr std::uint32_t kGlBool = 0x8B56, kGlInt = 0x1404, kGlUnsignedInt = 0x1405, kGlFloat = 0x1406,
                        kGlDouble = 0x140A;

struct SpirvModule {
    std::map<std::uint32_t, std::string> names;
    std::map<std::uint32_t, std::uint32_t> specIds, glTypes;
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> constants;  // id -> (type, bits)
};

void readInstruction(std::uint32_t op, std::span<const std::uint32_t> a, SpirvModule& m) {
    if (op == kOpName && a.size() >= 2) m.names[a[0]] = literalString(a.subspan(1));
    if (op == kOpDecorate && a.size() >= 3 && a[1] == kDecorationSpecId) m.specIds[a[0]] = a[2];
    if (op == kOpTypeBool && a.size() >= 1) m.glTypes[a[0]] = kGlBool;
    if (op == kOpTypeInt && a.size() >= 3) m.glTypes[a[0]] = a[2] ? kGlInt : kGlUnsignedInt;
    if (op == kOpTypeFloat && a.size() >= 2) m.glTypes[a[0]] = a[1] == 64 ? kGlDouble : kGlFloat;
    if ((op == kOpSpecConstantTrue || op == kOpSpecConstantFalse) && a.size() >= 2)
        m.constants[a[1]] = {a[0], op == kOpSpecConstantTrue ? 1u : 0u};
    if (op == kOpSpecConstant && a.size() >= 3) m.constants[a[1]] = {a[0], a[2]};
}

}  // namespace

void addSpecConstants(ProgramReflection& r, std::span<const std::uint32_t> words) {
    SpirvModule m;
    forEachInstruction(words, [&m](std::uint32_t op, std::span<const std::uint32_t> a, std::size_t) {
        readInstruction(op, a, m);
        return true;
    });
    for (const auto& entry : m.specIds) {  // no structured binding: Clang 14 cannot capture one
        const std::uint32_t id = entry.first, specId = entry.second;
        const auto constant = m.constants.find(id);
        const bool known =
            std::any_of(r.specConstants.begin(), r.specConstants.end(), [&](const auto& c) { return c.id == specId; });
        if (constant == m.constants.end() || known) continue;
        r.specConstants.push_back({m.names[id], specId, m.glTypes[constant->second.first], constant->second.second});
    }
    std::sort(r.specConstants.begin(), r.specConstants.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
}

}  // namespace prism::shaderc
