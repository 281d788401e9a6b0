// Part of stage 5 (validation_scheduler.hpp): the binding contract (contract.hpp) checked against the
// interface of a validated program's stages: a contract name must have the contract's type and
// location, and a near miss of one is an error (a warning against the built-in contract).
//
//   add(checkContract(contract, interfaces, locate));  // validator.cpp, after linking
#pragma once

#include <cstddef>
#include <vector>

#include "contract.hpp"
#include "diagnostics.hpp"
#include "interface_check.hpp"
#include "stage_interface.hpp"

namespace prism::shaderc {

// How far (edit distance) a shader's name may be from a contract name to count as a
// misspelling of it; farther names are the shader's own.
inline constexpr std::size_t kContractTypoDistance = 2;

// Checks the vertex stage's inputs and every stage's plain uniforms (not blocks): a name
// in the contract must have its type, and an explicit `layout(location = N)` on an
// attribute the contract's location (GL would bind N, the runtime feeds the contract's);
// a near miss is an error (a warning against the
// built-in contract); other names pass.
std::vector<Diagnostic> checkContract(const Contract& contract, const std::vector<StageInterface>& stages,
                                      const SourceLocator& locate);

}  // namespace prism::shaderc
