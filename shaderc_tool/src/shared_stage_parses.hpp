// Part of stage 5: each distinct stage of a set of programs parsed by glslang once, by the
// first program that needs it, shared by the others and freed after the last one (glslang's
// trees of every stage at once cost more in fresh memory than the parses). A stage is
// distinct by its kind, #version, token stream (validation_key.hpp) and SPIR-V environment.
// Used by the gl validation (validation_scheduler.hpp) and the es300 target, whose links
// leave a shared stage fit for the next program; the spirv target's relaxed-rules link
// rewrites its stages' uniform blocks, so it parses its own.
//
//   SharedStageParses parses(lists);  // lists[i]: program i's stages; empty if it will not ask
//   runPool(lists.size(), jobs, [&](std::size_t i) {
//       auto result = validateCompiledProgram(lists[i], parses.acquire(i), contract);
//       parses.release(i);
//   });
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

#include "validator.hpp"

namespace prism::shaderc {

class SharedStageParses {
  public:
    // Keeps a reference to `lists`, which must outlive it and not change.
    explicit SharedStageParses(const std::vector<std::vector<StageToValidate>>& lists);
    ~SharedStageParses();

    // Program i's stages, in its order; parses those no program has parsed yet (thread-safe).
    std::vector<std::shared_ptr<CompiledStage>> acquire(std::size_t program);
    // Program i is done with its stages (the caller has dropped what acquire gave it): a
    // stage no program will ask for again is freed.
    void release(std::size_t program);

    std::size_t distinct() const;  // distinct stages among the lists
    std::size_t parsed() const;    // glslang parses run so far (at most distinct())

  private:
    struct Slot;
    std::vector<const StageToValidate*> distinct_;  // points into lists_
    std::vector<std::vector<std::size_t>> refs_;    // [program]: indices into distinct_ and slots_
    std::unique_ptr<Slot[]> slots_;
    std::atomic<std::size_t> parsed_{0};
};

}  // namespace prism::shaderc
