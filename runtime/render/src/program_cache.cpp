// Lazily built, shared programs (see prism/render/program_cache.hpp).
#include "prism/render/program_cache.hpp"

namespace prism::render {

std::vector<std::string> ProgramCache::shaderNames() const {
    std::vector<std::string> names;
    for (const auto& s : catalog_.shaders) names.emplace_back(s.name);
    return names;
}

const catalog::Variant& ProgramCache::variantOf(std::string_view shader, const VariantValues& values) const {
    const auto* s = catalog::findShader(catalog_, shader);
    if (!s) {
        std::string known;
        for (const auto& n : shaderNames()) known += (known.empty() ? "" : ", ") + n;
        throw UnknownShaderError("unknown shader '" + std::string(shader) + "'; known shaders: " + known);
    }
    const catalog::Variant* found = nullptr;
    try {
        found = catalog::findVariant(*s, values);
    } catch (const catalog::VariantLookupError& e) {  // a misspelled axis or value, named with the known ones
        throw UnknownShaderError(e.what());
    }
    if (found) return *found;
    std::string known;
    for (const auto& v : s->variants) known += (known.empty() ? "" : "; ") + std::string(v.name);
    std::string asked;
    for (const auto& [n, val] : values) asked += (asked.empty() ? "" : ",") + n + "=" + val;
    throw UnknownShaderError("shader '" + std::string(shader) + "' has no variant '" + asked +
                             "'; generated variants: " + known);
}

gl::Program& ProgramCache::get(std::string_view shader, const VariantValues& values) {
    const auto& variant = variantOf(shader, values);
    auto key = std::make_pair(std::string(shader), std::string(variant.name));
    auto it = programs_.find(key);
    if (it == programs_.end()) {
        auto program = std::make_unique<gl::Program>(variant, catalog_.contractAttributes,
                                                     std::string(shader) + " (" + std::string(variant.name) + ")");
        it = programs_.emplace(std::move(key), std::move(program)).first;
    }
    return *it->second;
}

void ProgramCache::reload(std::string_view shader, std::string_view variantName, gl::Program program) {
    const auto* s = catalog::findShader(catalog_, shader);
    if (!s) {
        (void)variantOf(shader, {});  // throws, listing the known shaders
        return;
    }
    bool known = false;
    for (const auto& v : s->variants) known = known || v.name == variantName;
    if (!known) {
        std::string names;
        for (const auto& v : s->variants) names += (names.empty() ? "" : "; ") + std::string(v.name);
        throw UnknownShaderError("shader '" + std::string(shader) + "' has no variant '" + std::string(variantName) +
                                 "'; generated variants: " + names);
    }
    auto key = std::make_pair(std::string(shader), std::string(variantName));
    auto it = programs_.find(key);
    if (it == programs_.end())
        programs_.emplace(std::move(key), std::make_unique<gl::Program>(std::move(program)));
    else
        *it->second = std::move(program);  // same object: references from get() follow the swap
    ++reloads_;
}

std::vector<std::string> ProgramCache::builtVariants(std::string_view shader) const {
    std::vector<std::string> names;
    for (const auto& [key, program] : programs_)
        if (key.first == shader) names.push_back(key.second);
    return names;
}

}  // namespace prism::render
