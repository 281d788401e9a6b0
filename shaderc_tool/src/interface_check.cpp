// Matching of each stage's inputs against the previous stage's outputs.
#include "interface_check.hpp"

#include <algorithm>

namespace prism::shaderc {

Diagnostic diagnosticAt(const SourceLocator& locate, std::size_t stage, const InterfaceVariable& v, Severity severity,
                        std::string message) {
    Diagnostic d;
    d.severity = severity;
    d.file = locate.path ? locate.path(stage, v.sourceNumber) : std::string();
    d.line = v.line;
    d.column = v.column;
    d.message = std::move(message);
    if (locate.chain) d.includedFrom = locate.chain(stage, v.sourceNumber);
    return d;
}

namespace {

std::string describe(const InterfaceVariable& v, bool stripOuterArray) {
    InterfaceVariable copy = v;
    if (stripOuterArray) copy.arraySize = 0;
    return std::string(interpolationName(v.interpolation)) + " " + glslTypeWithArray(copy);
}

void checkPair(const std::vector<StageInterface>& stages, std::size_t prevIndex, std::size_t nextIndex,
               const SourceLocator& locate, std::vector<Diagnostic>& out) {
    const auto& prev = stages[prevIndex];
    const auto& next = stages[nextIndex];
    // Geometry inputs are arrays over the primitive's vertices: compare the element.
    const bool arrayedInputs = next.stage == catalog::Stage::Geometry;
    const std::string prevName(catalog::stageName(prev.stage));
    const std::string nextName(catalog::stageName(next.stage));

    for (const auto& in : next.variables) {
        if (in.storage != StorageKind::In) continue;
        auto match = std::find_if(prev.variables.begin(), prev.variables.end(), [&](const InterfaceVariable& o) {
            return o.storage == StorageKind::Out && o.name == in.name && o.isBlock == in.isBlock;
        });
        const std::string what = std::string(in.isBlock ? "block" : "input") + " '" + in.name + "'";
        if (match == prev.variables.end()) {
            out.push_back(diagnosticAt(locate, nextIndex, in, Severity::Error,
                                       nextName + " " + what + " is not written by the " + prevName + " stage (" +
                                           (locate.path ? locate.path(prevIndex, 0) : prevName) + "); declare `out " +
                                           glslTypeWithArray(in) + " " + in.name + ";` there or remove the input"));
            continue;
        }
        InterfaceVariable inElement = in;
        if (arrayedInputs) inElement.arraySize = 0;
        const bool typeDiffers = inElement.type != match->type || inElement.arraySize != match->arraySize;
        const bool interpDiffers = in.interpolation != match->interpolation;
        if (!typeDiffers && !interpDiffers) continue;
        std::string problem = typeDiffers ? "type" : "interpolation qualifier";
        auto d = diagnosticAt(locate, nextIndex, in, Severity::Error,
                              nextName + " " + what + " is `" + describe(in, arrayedInputs) + "` but the " + prevName +
                                  " output is `" + describe(*match, false) + "` (" + problem +
                                  " mismatch); make both declarations agree");
        d.notes.push_back(diagnosticAt(locate, prevIndex, *match, Severity::Note,
                                       "the " + prevName + " output '" + match->name + "' is declared here"));
        out.push_back(std::move(d));
    }
}

}  // namespace

std::vector<Diagnostic> checkStageInterfaces(const std::vector<StageInterface>& stages, const SourceLocator& locate) {
    std::vector<Diagnostic> out;
    for (std::size_t i = 1; i < stages.size(); ++i) checkPair(stages, i - 1, i, locate, out);
    return out;
}

}  // namespace prism::shaderc
