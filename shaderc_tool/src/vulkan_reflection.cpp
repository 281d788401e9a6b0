// A Vulkan program's layout from glslang's reflection and its SPIR-V (see vulkan_reflection.hpp).
#include "vulkan_reflection.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <map>
#include <tuple>

namespace prism::shaderc {
namespace {

using catalog::ResourceKind;

std::uint32_t setOf(const glslang::TType& type) {
    const auto& q = type.getQualifier();
    return q.hasSet() ? q.layoutSet : 0;
}

std::uint32_t arraySizeOf(const glslang::TType& type) {
    return type.isSizedArray() ? static_cast<std::uint32_t>(type.getOuterArraySize()) : 1;
}

// The descriptor kind of an opaque uniform (VkDescriptorType), from glslang's sampler type.
ResourceKind opaqueKind(const glslang::TType& type) {
    if (type.getBasicType() == glslang::EbtAccStruct) return ResourceKind::AccelerationStructure;
    const auto& s = type.getSampler();
    if (s.isSubpass()) return ResourceKind::InputAttachment;
    if (s.isPureSampler()) return ResourceKind::Sampler;
    if (s.isImage()) return s.isBuffer() ? ResourceKind::StorageTexelBuffer : ResourceKind::StorageImage;
    if (s.isBuffer()) return ResourceKind::UniformTexelBuffer;
    return s.isCombined() ? ResourceKind::CombinedImageSampler : ResourceKind::SampledImage;
}

bool isOpaque(const glslang::TType& type) {
    return type.getBasicType() == glslang::EbtSampler || type.getBasicType() == glslang::EbtAccStruct;
}

// Bytes a push-constant member takes (std430, Vulkan's default for push constants).
std::uint32_t memberSize(const glslang::TType& type) {
    int size = 0, stride = 0;
    glslang::TIntermediate::getBaseAlignment(type, size, stride, glslang::ElpStd430,
                                             type.getQualifier().layoutMatrix == glslang::ElmRowMajor);
    return static_cast<std::uint32_t>(size);
}

// `blocks[i]`: the resource of glslang's uniform block i, so its members can be listed.
void reflectBlocks(glslang::TProgram& program, ProgramReflection& r, std::vector<int>& pushBlocks,
                   std::map<int, std::size_t>& blocks) {
    for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
        const auto& b = program.getUniformBlock(i);
        const auto& type = *b.getType();
        if (type.getQualifier().layoutPushConstant) {
            pushBlocks.push_back(i);
            continue;
        }
        const auto kind = type.getQualifier().storage == glslang::EvqBuffer ? ResourceKind::StorageBuffer
                                                                            : ResourceKind::UniformBuffer;
        blocks[i] = r.resources.size();
        r.resources.push_back({b.name, setOf(type), static_cast<std::uint32_t>(std::max(0, b.getBinding())), kind,
                               static_cast<std::uint32_t>(std::max(0, b.size)), arraySizeOf(type)});
    }
    for (int i = 0; i < program.getNumBufferBlocks(); ++i) {
        const auto& b = program.getBufferBlock(i);
        r.resources.push_back({b.name, setOf(*b.getType()), static_cast<std::uint32_t>(std::max(0, b.getBinding())),
                               ResourceKind::StorageBuffer, static_cast<std::uint32_t>(std::max(0, b.size)),
                               arraySizeOf(*b.getType())});
    }
}

void reflectUniforms(glslang::TProgram& program, ProgramReflection& r, const std::vector<int>& pushBlocks,
                     const std::map<int, std::size_t>& blocks) {
    for (int i = 0; i < program.getNumUniformVariables(); ++i) {
        const auto& u = program.getUniform(i);
        const auto& type = *u.getType();
        if (std::find(pushBlocks.begin(), pushBlocks.end(), u.index) != pushBlocks.end())
            r.pushConstants.push_back({u.name, static_cast<std::uint32_t>(u.glDefineType),
                                       static_cast<std::uint32_t>(u.offset), memberSize(type)});
        else if (isOpaque(type))
            r.resources.push_back({u.name, setOf(type), static_cast<std::uint32_t>(std::max(0, u.getBinding())),
                                   opaqueKind(type), 0, arraySizeOf(type)});
        else if (const auto block = blocks.find(u.index); block != blocks.end())
            r.resources[block->second].members.push_back({u.name, static_cast<std::uint32_t>(u.glDefineType),
                                                          static_cast<std::uint32_t>(std::max(0, u.offset)),
                                                          std::max(1, u.size)});
    }
    for (auto& x : r.resources)
        std::sort(x.members.begin(), x.members.end(),
                  [](const auto& a, const auto& b) { return std::tie(a.offset, a.name) < std::tie(b.offset, b.name); });
}

}  // namespace

ProgramReflection reflectVulkanProgram(glslang::TProgram& program) {
    ProgramReflection r;
    if (!program.buildReflection(EShReflectionAllBlockVariables | EShReflectionSeparateBuffers)) return r;
    for (int i = 0; i < program.getNumPipeInputs(); ++i) {
        const auto& in = program.getPipeInput(i);
        const auto& q = in.getType()->getQualifier();
        if (in.name.rfind("gl_", 0) == 0) continue;
        r.attributes.push_back({in.name, static_cast<std::uint32_t>(in.glDefineType),
                                q.hasLocation() ? static_cast<int>(q.layoutLocation) : -1});
    }
    std::vector<int> pushBlocks;
    std::map<int, std::size_t> blocks;
    reflectBlocks(program, r, pushBlocks, blocks);
    reflectUniforms(program, r, pushBlocks, blocks);
    std::sort(r.attributes.begin(), r.attributes.end(), [](const auto& a, const auto& b) {
        return a.location != b.location ? a.location < b.location : a.name < b.name;
    });
    std::sort(r.resources.begin(), r.resources.end(), [](const auto& a, const auto& b) {
        return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    });
    std::sort(r.pushConstants.begin(), r.pushConstants.end(),
              [](const auto& a, const auto& b) { return std::tie(a.offset, a.name) < std::tie(b.offset, b.name); });
    return r;
}

namespace {

// SPIR-V opcodes and decorations read here (SPIR-V specification, section 3).
constexpr std::uint32_t kOpName = 5, kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpSpecConstantTrue = 48,
                        kOpSpecConstantFalse = 49, kOpSpecConstant = 50, kOpDecorate = 71, kDecorationSpecId = 1;
constexpr std::uint32_t kGlBool = 0x8B56, kGlInt = 0x1404, kGlUnsignedInt = 0x1405, kGlFloat = 0x1406,
                        kGlDouble = 0x140A;

std::string literalString(std::span<const std::uint32_t> operands) {
    std::string s;
    for (auto word : operands)
        for (int byte = 0; byte < 4; ++byte) {
            const char c = static_cast<char>((word >> (8 * byte)) & 0xFF);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

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
    for (std::size_t at = 5; at < words.size();) {  // past the 5-word header
        const std::uint32_t count = words[at] >> 16;
        if (count == 0 || at + count > words.size()) break;
        readInstruction(words[at] & 0xFFFF, words.subspan(at + 1, count - 1), m);
        at += count;
    }
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
