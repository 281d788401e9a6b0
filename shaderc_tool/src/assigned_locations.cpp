// Overlaps among the locations glslang assigned for the spirv target (assigned_locations.hpp).
#include "assigned_locations.hpp"

#include <string>

namespace prism::shaderc {
namespace {

bool overlap(const InterfaceVariable& a, const InterfaceVariable& b) {
    return a.location < b.location + b.locationSlots && b.location < a.location + a.locationSlots;
}

bool placedByGlslang(const StageInterface& before, std::size_t v) {
    return before.variables[v].location < 0;
}

// The first variable of stage `after` with `v`'s storage whose locations `v` overlaps.
const InterfaceVariable* overlapped(const StageInterface& after, std::size_t v) {
    const auto& placed = after.variables[v];
    for (std::size_t o = 0; o < after.variables.size(); ++o) {
        const auto& other = after.variables[o];
        if (o != v && other.storage == placed.storage && other.location >= 0 && overlap(placed, other)) return &other;
    }
    return nullptr;
}

void checkStage(const StageInterface& before, const StageInterface& after, std::size_t stage,
                const SourceLocator& locate, std::vector<Diagnostic>& out) {
    const std::string stageName(catalog::stageName(after.stage));
    for (std::size_t v = 0; v < after.variables.size(); ++v) {
        const auto& placed = after.variables[v];
        const bool io = placed.storage == StorageKind::In || placed.storage == StorageKind::Out;
        if (!io || placed.location < 0 || !placedByGlslang(before, v)) continue;
        const auto* other = overlapped(after, v);
        if (other == nullptr) continue;
        const std::string kind = placed.storage == StorageKind::In ? "input" : "output";
        auto d = diagnosticAt(locate, stage, placed, Severity::Error,
                              "for target spirv, glslang puts the " + stageName + " " + kind + " '" + placed.name +
                                  "' at location " + std::to_string(placed.location) + ", which '" + other->name +
                                  "' already takes (glslang's automatic locations do not avoid explicit ones); give "
                                  "every " +
                                  kind + " of this stage a layout(location), or none");
        d.notes.push_back(
            diagnosticAt(locate, stage, *other, Severity::Note,
                         "'" + other->name + "' is at location " + std::to_string(other->location) + " here"));
        out.push_back(std::move(d));
    }
}

}  // namespace

std::vector<Diagnostic> checkAssignedLocations(const std::vector<StageInterface>& before,
                                               const std::vector<StageInterface>& after, const SourceLocator& locate) {
    std::vector<Diagnostic> out;
    for (std::size_t s = 0; s < before.size() && s < after.size(); ++s)
        if (before[s].variables.size() == after[s].variables.size()) checkStage(before[s], after[s], s, locate, out);
    return out;
}

}  // namespace prism::shaderc
