// Which files are stages (stage_files.hpp).
#include "stage_files.hpp"

#include <algorithm>
#include <array>

namespace prism::shaderc {
namespace {

using catalog::Stage;
constexpr std::array kGlStageKinds = {Stage::Vertex,   Stage::TessControl, Stage::TessEvaluation,
                                      Stage::Geometry, Stage::Fragment,    Stage::Compute};
constexpr std::array kVulkanOnlyStageKinds = {Stage::Mesh,   Stage::Task,       Stage::RayGen, Stage::Intersect,
                                              Stage::AnyHit, Stage::ClosestHit, Stage::Miss,   Stage::Callable};

// ".a, .b or .c"
template <std::size_t N>
std::string extensionList(const std::array<Stage, N>& kinds) {
    std::string list;
    for (std::size_t i = 0; i < N; ++i)
        list += (i == 0 ? "." : i + 1 == N ? " or ." : ", .") + std::string(catalog::stageName(kinds[i]));
    return list;
}

}  // namespace

bool isVulkanOnly(Stage s) {
    return std::find(kVulkanOnlyStageKinds.begin(), kVulkanOnlyStageKinds.end(), s) != kVulkanOnlyStageKinds.end();
}

std::optional<Stage> stageOfPath(const std::filesystem::path& p) {
    const auto ext = p.extension().string();
    if (ext.size() < 2) return std::nullopt;
    for (auto stage : kGlStageKinds)
        if (ext.substr(1) == catalog::stageName(stage)) return stage;
    for (auto stage : kVulkanOnlyStageKinds)
        if (ext.substr(1) == catalog::stageName(stage)) return stage;
    return std::nullopt;
}

std::string stageExtensionList() {
    return extensionList(kGlStageKinds) + " (with --client vulkan also " + extensionList(kVulkanOnlyStageKinds) + ")";
}

}  // namespace prism::shaderc
