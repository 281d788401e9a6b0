// Variant resolution and validity for the catalogue panel (variant_choice.hpp).
#include "variant_choice.hpp"

namespace prism::viewer {

namespace {
bool hasAxis(const catalog::Shader& shader, std::string_view name) {
    for (const auto& a : shader.axes)
        if (a.name == name) return true;
    return false;
}

// For the panel a value its axis lacks is one more combination that does not exist, not
// an error (findVariant throws VariantLookupError for it).
const catalog::Variant* variantOrNull(const catalog::Shader& shader, const render::VariantValues& values) {
    try {
        return catalog::findVariant(shader, values);
    } catch (const catalog::VariantLookupError&) {
        return nullptr;
    }
}
}  // namespace

render::VariantValues effectiveVariant(const catalog::Shader& shader, const render::FeatureSet& features,
                                       const render::VariantValues& picks) {
    render::VariantValues known;
    for (const auto& p : picks)
        if (hasAxis(shader, p.first)) known.push_back(p);
    render::VariantValues values = render::variantFor(shader, features, known);
    if (variantOrNull(shader, values)) return values;
    return render::variantFor(shader, features, {});
}

bool isValidChoice(const catalog::Shader& shader, const render::VariantValues& current, std::string_view axis,
                   std::string_view value) {
    render::VariantValues v = current;
    setAxis(v, axis, value);
    return variantOrNull(shader, v) != nullptr;
}

void setAxis(render::VariantValues& values, std::string_view axis, std::string_view value) {
    for (auto& [n, v] : values)
        if (n == axis) {
            v = std::string(value);
            return;
        }
    values.emplace_back(std::string(axis), std::string(value));
}

std::string whyNotAVariant(const catalog::Shader& shader, const render::FeatureSet& features,
                           const render::VariantValues& picks) {
    for (const auto& [axis, value] : picks) {
        const catalog::VariantAxis* found = nullptr;
        for (const auto& a : shader.axes)
            if (a.name == axis) found = &a;
        std::string known;
        if (!found) {
            for (const auto& a : shader.axes) known += (known.empty() ? "" : ", ") + std::string(a.name);
            return std::string(shader.name) + " has no variant axis '" + axis +
                   "' (its axes: " + (known.empty() ? "none" : known) + ")";
        }
        bool valid = false;
        for (const auto& v : found->values) {
            valid = valid || v == value;
            known += (known.empty() ? "" : ", ") + std::string(v);
        }
        if (!valid)
            return axis + "=" + value + " is not a value of " + std::string(shader.name) + "'s axis " + axis +
                   " (values: " + known + ")";
    }
    if (!variantOrNull(shader, render::variantFor(shader, features, picks)))
        return std::string(shader.name) + " has no generated variant " +
               variantLabel(render::variantFor(shader, features, picks));
    return {};
}

std::string variantLabel(const render::VariantValues& values) {
    std::string out;
    for (const auto& [n, v] : values) out += (out.empty() ? "" : ",") + n + "=" + v;
    return out.empty() ? "default" : out;
}

}  // namespace prism::viewer
