// Checks the stages' interface against the binding contract (see contract_check.hpp).
#include "contract_check.hpp"

#include <algorithm>
#include <string>

#include "prism/catalog/did_you_mean.hpp"

namespace prism::shaderc {
namespace {

std::string contractFiles(const Contract& c) {
    if (c.builtIn) return "Prism's contract, built into prism-shaderc";
    std::string s;
    for (const auto& f : c.files) s += (s.empty() ? "" : ", ") + f;
    return s;
}

// The contract name that `name` misspells (within kContractTypoDistance, not equal), or "".
template <class T>
std::string misspelledName(const std::string& name, const std::vector<T>& known) {
    std::vector<std::string> names;
    for (const auto& k : known) names.push_back(k.name);
    return catalog::closestName(name, names, kContractTypoDistance);
}

// Against the built-in contract, which the user never chose, problems are warnings.
Severity severityFor(const Contract& c) {
    return c.builtIn ? Severity::Warning : Severity::Error;
}

std::string remedy(const Contract& c) {
    return c.builtIn ? "; fix the name, or give prism_add_shaders() a CONTRACT (--contract) that declares it"
                     : "; fix the name or add it to the contract";
}

void checkAttribute(const Contract& c, std::size_t s, const InterfaceVariable& v, const SourceLocator& locate,
                    std::vector<Diagnostic>& out) {
    auto it = std::find_if(c.attributes.begin(), c.attributes.end(), [&](const auto& a) { return a.name == v.name; });
    if (it == c.attributes.end()) {
        const std::string meant = misspelledName(v.name, c.attributes);
        if (meant.empty()) return;  // far from every contract name: the shader's own attribute
        out.push_back(diagnosticAt(locate, s, v, severityFor(c),
                                   "vertex attribute '" + v.name + "' is not in the binding contract (" +
                                       contractFiles(c) + "), so the runtime would never feed it (did you mean '" +
                                       meant + "'?)" + remedy(c)));
    } else if (it->type != glslTypeWithArray(v)) {
        out.push_back(diagnosticAt(locate, s, v, severityFor(c),
                                   "vertex attribute '" + v.name + "' is `" + glslTypeWithArray(v) +
                                       "` but the contract (" + contractFiles(c) + ") supplies `" + it->type + "`"));
    } else if (v.location >= 0 && v.location != it->location) {
        // An error even against the built-in contract: the runtime would feed another attribute's data.
        auto d =
            diagnosticAt(locate, s, v, Severity::Error,
                         "vertex attribute '" + v.name + "' is at layout(location = " + std::to_string(v.location) +
                             ") but the binding contract puts it at location " + std::to_string(it->location) +
                             "; drop the layout qualifier or use location " + std::to_string(it->location));
        d.notes.push_back(
            makeError(c.builtIn || it->entry.empty() ? contractFiles(c) : it->entry, 0, 0,
                      "the contract's entry: '" + it->name + "' at location " + std::to_string(it->location)));
        d.notes.back().severity = Severity::Note;
        out.push_back(std::move(d));
    }
}

void checkUniform(const Contract& c, std::size_t s, const InterfaceVariable& v, const SourceLocator& locate,
                  std::vector<Diagnostic>& out) {
    const std::string files = contractFiles(c);
    auto it = std::find_if(c.uniforms.begin(), c.uniforms.end(), [&](const auto& u) { return u.name == v.name; });
    if (it == c.uniforms.end()) {
        const std::string meant = misspelledName(v.name, c.uniforms);
        if (meant.empty()) return;  // far from every contract name: the shader's own uniform
        out.push_back(diagnosticAt(locate, s, v, severityFor(c),
                                   "uniform '" + v.name + "' is not in the binding contract (" + files +
                                       "), so the runtime never sets it (did you mean '" + meant + "'?)" + remedy(c)));
    } else if (it->type != v.type) {
        out.push_back(diagnosticAt(locate, s, v, severityFor(c),
                                   "uniform '" + v.name + "' is `" + glslTypeWithArray(v) + "` but the contract (" +
                                       files + ") supplies `" + it->type +
                                       (it->array ? "[" + std::to_string(it->array) + "]" : "") + "`"));
    } else if ((v.arraySize != 0) != (it->array != 0) || v.arraySize > it->array || v.arraySize < 0) {
        out.push_back(diagnosticAt(
            locate, s, v, severityFor(c),
            "uniform '" + v.name + "' is `" + glslTypeWithArray(v) + "` but the contract (" + files + ") supplies " +
                (it->array ? "at most " + std::to_string(it->array) + " elements" : "a single value")));
    }
}

}  // namespace

std::vector<Diagnostic> checkContract(const Contract& contract, const std::vector<StageInterface>& stages,
                                      const SourceLocator& locate) {
    std::vector<Diagnostic> out;
    if (contract.empty()) return out;
    for (std::size_t s = 0; s < stages.size(); ++s) {
        for (const auto& v : stages[s].variables) {
            if (v.storage == StorageKind::In && stages[s].stage == catalog::Stage::Vertex)
                checkAttribute(contract, s, v, locate, out);
            else if (v.storage == StorageKind::Uniform && !v.isBlock)
                checkUniform(contract, s, v, locate, out);
        }
    }
    return out;
}

}  // namespace prism::shaderc
