// The names and the stage kinds of prism-shaderc's output targets (targets.hpp).
#include "targets.hpp"

#include <algorithm>

#include "did_you_mean.hpp"

namespace prism::shaderc {

std::string_view targetName(Target target) {
    switch (target) {
        case Target::Gl: return "gl";
        case Target::Es300: return "es300";
        case Target::Spirv: return "spirv";
    }
    return "?";
}

std::string targetDescription(Target target) {
    switch (target) {
        case Target::Gl: return "gl (desktop GLSL)";
        case Target::Es300: return "es300 (GLSL ES 3.00: WebGL2, GLES 3.0)";
        case Target::Spirv: return "spirv (SPIR-V for Vulkan)";
    }
    return "?";
}

std::optional<Target> targetNamed(std::string_view name) {
    for (const Target t : kAllTargets)
        if (targetName(t) == name) return t;
    return std::nullopt;
}

std::string parseTargetList(std::string_view list, std::vector<Target>& targets) {
    std::vector<Target> found;
    std::size_t pos = 0;
    while (pos < list.size()) {
        const auto end = std::min(list.find_first_of(", \t", pos), list.size());
        const std::string word(list.substr(pos, end - pos));
        pos = end + 1;
        if (word.empty()) continue;
        const auto target = targetNamed(word);
        if (!target) {
            const std::vector<std::string> known = {"gl", "es300", "spirv"};
            return "unknown target '" + word + "'" + didYouMean(word, known) + "; the targets are gl, es300 and spirv";
        }
        found.push_back(*target);
    }
    if (found.empty()) return "no target named; the targets are gl, es300 and spirv";
    targets.clear();
    for (const Target t : kAllTargets)
        if (hasTarget(found, t)) targets.push_back(t);
    return {};
}

std::string targetListText(const std::vector<Target>& targets) {
    std::string text;
    for (const Target t : targets) text += (text.empty() ? "" : " ") + std::string(targetName(t));
    return text;
}

bool hasTarget(const std::vector<Target>& targets, Target target) {
    return std::find(targets.begin(), targets.end(), target) != targets.end();
}

bool targetRunsStage(Target target, catalog::Stage stage) {
    if (target != Target::Es300) return true;
    return stage == catalog::Stage::Vertex || stage == catalog::Stage::Fragment;
}

}  // namespace prism::shaderc
