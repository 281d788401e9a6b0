// One glslang parse per distinct stage, shared by the programs that use it (shared_stage_parses.hpp).
#include "shared_stage_parses.hpp"

#include <atomic>
#include <map>
#include <mutex>
#include <string>

namespace prism::shaderc {

struct SharedStageParses::Slot {
    std::once_flag parsed;
    std::shared_ptr<CompiledStage> compiled;
    std::atomic<std::size_t> users{0};
};

SharedStageParses::SharedStageParses(const std::vector<std::vector<StageToValidate>>& lists) : refs_(lists.size()) {
    std::map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < lists.size(); ++i)
        for (const auto& st : lists[i]) {
            const std::string key = std::to_string(static_cast<int>(st.stage)) + " " + st.resolved.versionDirective +
                                    " " + st.resolved.validationKey +
                                    (st.rules.spirvEnv ? " " + std::string(spirvEnvName(*st.rules.spirvEnv)) : "");
            auto [it, fresh] = index.try_emplace(key, distinct_.size());
            if (fresh) distinct_.push_back(&st);
            refs_[i].push_back(it->second);
        }
    slots_ = std::make_unique<Slot[]>(distinct_.size());
    for (const auto& refs : refs_)
        for (const auto k : refs) ++slots_[k].users;
}

SharedStageParses::~SharedStageParses() = default;

std::vector<std::shared_ptr<CompiledStage>> SharedStageParses::acquire(std::size_t program) {
    std::vector<std::shared_ptr<CompiledStage>> stages;
    for (const auto k : refs_[program]) {
        std::call_once(slots_[k].parsed, [&] {
            slots_[k].compiled = compileStage(*distinct_[k]);
            ++parsed_;
        });
        stages.push_back(slots_[k].compiled);
    }
    return stages;
}

void SharedStageParses::release(std::size_t program) {
    for (const auto k : refs_[program])
        if (--slots_[k].users == 0) slots_[k].compiled.reset();
}

std::size_t SharedStageParses::distinct() const {
    return distinct_.size();
}

std::size_t SharedStageParses::parsed() const {
    return parsed_;
}

}  // namespace prism::shaderc
