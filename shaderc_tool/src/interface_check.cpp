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

// Inputs of the stages after the vertex stage (tesc, tese, geom) and the outputs of the
// tessellation control stage are arrays over the patch's or primitive's vertices, each
// element one vertex's value; patch variables are not.
bool perVertexArray(catalog::Stage stage, const InterfaceVariable& v) {
    if (v.patch) return false;
    // A mesh stage's outputs are arrays over its vertices, or (perprimitiveEXT) its primitives.
    if (v.storage == StorageKind::Out) return stage == catalog::Stage::TessControl || stage == catalog::Stage::Mesh;
    return stage == catalog::Stage::Geometry || stage == catalog::Stage::TessControl ||
           stage == catalog::Stage::TessEvaluation;
}

// What one vertex (or the patch) gets: the variable without its per-vertex array.
InterfaceVariable element(catalog::Stage stage, const InterfaceVariable& v) {
    InterfaceVariable e = v;
    if (perVertexArray(stage, v)) e.arraySize = 0;
    return e;
}

std::string describe(const InterfaceVariable& v) {
    const std::string qualifier = v.perPrimitive ? "perprimitiveEXT" : std::string(interpolationName(v.interpolation));
    return std::string(v.patch ? "patch " : "") + qualifier + " " + glslTypeWithArray(v);
}

// The output `in` reads, as GL links them: the output at the same explicit location
// whatever its name; else the output of the same name, unless both have locations that differ.
const InterfaceVariable* matchOf(const StageInterface& prev, const InterfaceVariable& in) {
    const auto isOut = [&](const InterfaceVariable& o) {
        return o.storage == StorageKind::Out && o.isBlock == in.isBlock;
    };
    if (in.location >= 0)
        for (const auto& o : prev.variables)
            if (isOut(o) && o.location == in.location) return &o;
    for (const auto& o : prev.variables)
        if (isOut(o) && o.name == in.name && (o.location < 0 || in.location < 0)) return &o;
    return nullptr;
}

std::string locationText(const InterfaceVariable& v) {
    return v.location >= 0 ? " (location " + std::to_string(v.location) + ")" : "";
}

void checkPair(const std::vector<StageInterface>& stages, std::size_t prevIndex, std::size_t nextIndex,
               const SourceLocator& locate, std::vector<Diagnostic>& out) {
    const auto& prev = stages[prevIndex];
    const auto& next = stages[nextIndex];
    const std::string prevName(catalog::stageName(prev.stage));
    const std::string nextName(catalog::stageName(next.stage));

    for (const auto& in : next.variables) {
        if (in.storage != StorageKind::In) continue;
        const auto* match = matchOf(prev, in);
        const std::string what = std::string(in.isBlock ? "block" : "input") + " '" + in.name + "'" + locationText(in);
        const InterfaceVariable inElement = element(next.stage, in);
        if (match == nullptr) {
            out.push_back(diagnosticAt(locate, nextIndex, in, Severity::Error,
                                       nextName + " " + what + " is not written by the " + prevName + " stage (" +
                                           (locate.path ? locate.path(prevIndex, 0) : prevName) + "); declare `out " +
                                           glslTypeWithArray(inElement) + " " + in.name + ";` there" +
                                           (in.location >= 0 ? " at that location" : "") + " or remove the input"));
            continue;
        }
        const InterfaceVariable outElement = element(prev.stage, *match);
        // Blocks that meet by location match by their members' types, whatever their names.
        const bool blockPair = in.isBlock && match->isBlock && in.name != match->name;
        const bool typeDiffers =
            (blockPair ? in.memberTypes != match->memberTypes : inElement.type != outElement.type) ||
            inElement.arraySize != outElement.arraySize;
        // A per-primitive value is not interpolated: its interpolation qualifiers need not agree.
        const bool interpolated = !in.perPrimitive && !match->perPrimitive;
        const bool interpDiffers = (interpolated && in.interpolation != match->interpolation) ||
                                   in.patch != match->patch || in.perPrimitive != match->perPrimitive;
        if (!typeDiffers && !interpDiffers) continue;
        std::string problem = typeDiffers                              ? "type"
                              : in.patch != match->patch               ? "patch qualifier"
                              : in.perPrimitive != match->perPrimitive ? "perprimitiveEXT qualifier"
                                                                       : "interpolation qualifier";
        auto d =
            diagnosticAt(locate, nextIndex, in, Severity::Error,
                         nextName + " " + what + " is `" + describe(inElement) + "` but the " + prevName + " output" +
                             (match->name == in.name ? "" : " '" + match->name + "'" + locationText(*match)) + " is `" +
                             describe(outElement) + "` (" + problem + " mismatch); make both declarations agree");
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
