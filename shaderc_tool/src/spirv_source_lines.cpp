// Source numbers as OpLine file names while a stage's SPIR-V with line info is generated.
#include "spirv_source_lines.hpp"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <map>
#include <utility>

#include "spirv_codegen.hpp"

namespace prism::shaderc {
namespace {

// Names every node of a tree by its source number, remembering each node's own location
// to put back.
class SourceNumberNames : public glslang::TIntermTraverser {
  public:
    ~SourceNumberNames() override {
        for (auto& [node, loc] : saved_) node->setLoc(loc);
    }
    void visitSymbol(glslang::TIntermSymbol* n) override { rename(n); }
    void visitConstantUnion(glslang::TIntermConstantUnion* n) override { rename(n); }
    bool visitBinary(glslang::TVisit, glslang::TIntermBinary* n) override { return rename(n); }
    bool visitUnary(glslang::TVisit, glslang::TIntermUnary* n) override { return rename(n); }
    bool visitSelection(glslang::TVisit, glslang::TIntermSelection* n) override { return rename(n); }
    bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* n) override { return rename(n); }
    bool visitLoop(glslang::TVisit, glslang::TIntermLoop* n) override { return rename(n); }
    bool visitBranch(glslang::TVisit, glslang::TIntermBranch* n) override { return rename(n); }
    bool visitSwitch(glslang::TVisit, glslang::TIntermSwitch* n) override { return rename(n); }

  private:
    bool rename(::TIntermNode* node) {
        if (!saved_.try_emplace(node, node->getLoc()).second) return true;  // visited before (pre and post)
        glslang::TSourceLoc loc = node->getLoc();
        auto& name = names_[loc.string];
        if (name == nullptr) name = glslang::NewPoolTString(std::to_string(loc.string < 0 ? 0 : loc.string).c_str());
        loc.name = name;
        node->setLoc(loc);
        return true;
    }
    std::map<::TIntermNode*, glslang::TSourceLoc> saved_;
    std::map<int, glslang::TString*> names_;
};

}  // namespace

bool generateSpirvWithSourceNumbers(glslang::TProgram& program, EShLanguage stage, std::vector<std::uint32_t>& words,
                                    std::string& log) {
    auto* intermediate = program.getIntermediate(stage);
    if (intermediate == nullptr || intermediate->getTreeRoot() == nullptr) return false;
    SourceNumberNames names;
    intermediate->getTreeRoot()->traverse(&names);
    return generateSpirv(program, stage, words, log, true);
}

}  // namespace prism::shaderc
