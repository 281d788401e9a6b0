// What prism-shaderc can produce from one module source (docs/targets.md): `gl` (desktop
// GLSL, today's output), `es300` (GLSL ES 3.00 for WebGL2 and GLES 3.0) and `spirv`. The one
// place that names them, for --target, prism_add_shaders(TARGETS) and a stage's
// `#pragma prism targets gl spirv`, and that says which stage kinds a target can run.
//
//   std::vector<Target> targets;
//   if (auto error = parseTargetList("gl,es300", targets); !error.empty()) ...  // usage error
//   if (!targetRunsStage(Target::Es300, catalog::Stage::Geometry)) ...         // refused
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

namespace prism::shaderc {

enum class Target : std::uint8_t { Gl, Es300, Spirv };

inline constexpr Target kAllTargets[] = {Target::Gl, Target::Es300, Target::Spirv};

std::string_view targetName(Target target);

// What the target is, for messages: "es300 (GLSL ES 3.00: WebGL2, GLES 3.0)".
std::string targetDescription(Target target);

std::optional<Target> targetNamed(std::string_view name);

// Reads a list of target names separated by commas or blanks ("gl,es300 spirv") into
// `targets` (in kAllTargets order, each once); returns "" or the error, which names the
// bad word, says what was meant where a name is close, and lists the known targets.
std::string parseTargetList(std::string_view list, std::vector<Target>& targets);

// "gl es300": the names of `targets`, separated by blanks.
std::string targetListText(const std::vector<Target>& targets);

bool hasTarget(const std::vector<Target>& targets, Target target);

// False where the target's API has no such stage: ES 3.00 has neither geometry nor compute.
bool targetRunsStage(Target target, catalog::Stage stage);

}  // namespace prism::shaderc
