// The descriptor and ray-tracing data checks across a Vulkan program's stages.
#include "vulkan_stage_rules.hpp"

#include <map>
#include <optional>
#include <tuple>

namespace prism::shaderc {
namespace {

struct Declaration {
    std::size_t stage;
    const InterfaceVariable* variable;
};

// What a pipeline layout's binding must agree on: the descriptor's kind and shape and its count.
std::string descriptorShape(const InterfaceVariable& v) {
    const std::string count = v.arraySize == 0 ? "" : v.arraySize < 0 ? "[]" : "[" + std::to_string(v.arraySize) + "]";
    if (v.isBlock) return (v.storage == StorageKind::Buffer ? "storage buffer" : "uniform buffer") + count;
    return v.type + count;
}

// Adds "error at `later`, note at `first`" when the two disagree on `shape`.
template <class Shape>
void compareWithFirst(const std::vector<StageInterface>& stages, const Declaration& first, const Declaration& later,
                      const std::string& what, Shape shape, const SourceLocator& locate, std::vector<Diagnostic>& out) {
    if (shape(*first.variable) == shape(*later.variable)) return;
    const std::string laterStage(catalog::stageName(stages[later.stage].stage));
    const std::string firstStage(catalog::stageName(stages[first.stage].stage));
    auto d = diagnosticAt(locate, later.stage, *later.variable, Severity::Error,
                          laterStage + " stage declares " + what + " as `" + shape(*later.variable) + "` but the " +
                              firstStage + " stage declares it as `" + shape(*first.variable) +
                              "`; make both declarations agree");
    d.notes.push_back(diagnosticAt(locate, first.stage, *first.variable, Severity::Note,
                                   "the " + firstStage + " stage's declaration is here"));
    out.push_back(std::move(d));
}

bool isDescriptor(const InterfaceVariable& v) {
    return (v.storage == StorageKind::Uniform || v.storage == StorageKind::Buffer) && !v.pushConstant && v.binding >= 0;
}

// The ray-tracing data a variable is, as (kind, location): payloads and callable data by
// location, the hit attribute alone; none for anything else.
std::optional<std::pair<std::string, int>> rayTracingSlot(const InterfaceVariable& v) {
    switch (v.storage) {
        case StorageKind::RayPayload:
        case StorageKind::RayPayloadIn: return std::pair{std::string("ray payload"), v.location};
        case StorageKind::CallableData:
        case StorageKind::CallableDataIn: return std::pair{std::string("callable data"), v.location};
        case StorageKind::HitAttribute: return std::pair{std::string("hit attribute"), -1};
        default: return std::nullopt;
    }
}

// A payload's type as the stages must agree on it: a struct by its members' types (the stages
// may name their structs differently; SPIR-V types carry no names), with its array size.
std::string dataShape(const InterfaceVariable& v) {
    if (v.memberTypes.empty()) return glslTypeWithArray(v);
    const std::string array = v.arraySize == 0 ? "" : "[" + std::to_string(v.arraySize) + "]";
    return "struct { " + v.memberTypes + "}" + array;
}

}  // namespace

std::vector<Diagnostic> checkDescriptorBindings(const std::vector<StageInterface>& stages,
                                                const SourceLocator& locate) {
    std::vector<Diagnostic> out;
    std::map<std::pair<int, int>, Declaration> first;  // (set, binding) -> the first stage's declaration
    for (std::size_t s = 0; s < stages.size(); ++s)
        for (const auto& v : stages[s].variables) {
            if (!isDescriptor(v)) continue;
            const auto [it, fresh] = first.try_emplace({v.set, v.binding}, Declaration{s, &v});
            if (fresh || it->second.stage == s) continue;
            const std::string what =
                "set " + std::to_string(v.set) + ", binding " + std::to_string(v.binding) + " ('" + v.name + "')";
            compareWithFirst(stages, it->second, {s, &v}, what, descriptorShape, locate, out);
        }
    return out;
}

std::vector<Diagnostic> checkRayTracingData(const std::vector<StageInterface>& stages, const SourceLocator& locate) {
    std::vector<Diagnostic> out;
    std::map<std::pair<std::string, int>, Declaration> first;
    for (std::size_t s = 0; s < stages.size(); ++s)
        for (const auto& v : stages[s].variables) {
            const auto slot = rayTracingSlot(v);
            if (!slot) continue;
            const auto [it, fresh] = first.try_emplace(*slot, Declaration{s, &v});
            if (fresh || it->second.stage == s) continue;
            const std::string what = "the " + slot->first +
                                     (slot->second >= 0 ? " at location " + std::to_string(slot->second) : "") + " ('" +
                                     v.name + "')";
            compareWithFirst(stages, it->second, {s, &v}, what, dataShape, locate, out);
        }
    return out;
}

}  // namespace prism::shaderc
