// Part of stage 5 (validation_scheduler.hpp): compiles every stage of one variant with
// glslang, links the program, runs the cross-stage interface check and the contract check,
// and maps each glslang message back to the module's own file:line (with its "included
// from" chain).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <prism/catalog/shader_catalog.hpp>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "include_resolver.hpp"
#include "reflection.hpp"
#include "spirv_codegen.hpp"
#include "target_rules.hpp"

namespace glslang {
class TProgram;
class TShader;
}  // namespace glslang

namespace prism::shaderc {

// A further check of a linked program (the es300 limits, es300_limits.hpp): reads the
// program and its shaders (in stage order), returns what it found.
using LinkedProgramCheck =
    std::function<std::vector<Diagnostic>(glslang::TProgram&, const std::vector<glslang::TShader*>&)>;

struct StageToValidate {
    catalog::Stage stage;
    std::string path;  // the stage file, for errors without a line
    ResolvedStage resolved;
    // How it is compiled, checked and linked: the client's (Options::rules) or a target's
    // (target_rules.hpp); the default is the OpenGL client's, driver GLSL.
    TargetRules rules = {};
    std::string program = {};  // the program's name, for SPIR-V messages
};

struct ValidatedVariant {
    bool ok = false;
    ProgramReflection reflection;  // with rules.spirvEnv, also each stage's SPIR-V
    std::vector<Diagnostic> diagnostics;
};

// Call once per process before any validateProgram (thread-safe afterwards).
void initializeValidator();
void finalizeValidator();

// Thread-safe: each call uses its own glslang objects.
ValidatedVariant validateProgram(const std::vector<StageToValidate>& stages, const Contract& contract,
                                 const LinkedProgramCheck& check = {});

// One stage parsed by glslang, shareable by the programs whose stage has the same
// token stream (validation_scheduler.hpp). Its diagnostics speak of the text it was
// compiled from.
struct CompiledStage;
std::shared_ptr<CompiledStage> compileStage(const StageToValidate& stage);  // thread-safe
bool compiledCleanly(const CompiledStage& stage);                           // parsed without any message

// validateProgram with the stages compiled before, possibly shared with other programs
// (each stage's lock is held while it is linked and read). glslang's link keeps state
// in a shared stage, so a caller re-validates a program whose result has diagnostics
// with validateProgram, on private stages.
ValidatedVariant validateCompiledProgram(const std::vector<StageToValidate>& stages,
                                         const std::vector<std::shared_ptr<CompiledStage>>& compiled,
                                         const Contract& contract, const LinkedProgramCheck& check = {});

}  // namespace prism::shaderc
