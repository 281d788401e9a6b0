// scene::Scene features to variant values (see prism/render/feature_variants.hpp).
#include "prism/render/feature_variants.hpp"

#include <charconv>
#include <limits>
#include <stdexcept>

namespace prism::render {
namespace {

int asNumber(std::string_view text) {
    int v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    return ec == std::errc() && end == text.data() + text.size() ? v : -1;
}

// The smallest value of a numeric axis that holds `count`.
std::string smallestHolding(const catalog::Shader& shader, const catalog::VariantAxis& axis, int count) {
    int best = std::numeric_limits<int>::max();
    for (auto value : axis.values) {
        const int v = asNumber(value);
        if (v >= count && v < best) best = v;
    }
    if (best == std::numeric_limits<int>::max())
        throw std::invalid_argument("shader '" + std::string(shader.name) + "' has no variant with " +
                                    std::to_string(count) + " " + std::string(axis.name) +
                                    "; reduce the lights or add a value to its #pragma prism variant");
    return std::to_string(best);
}

}  // namespace

FeatureSet featuresOf(const view::Lights& lights, bool fog) {
    return {static_cast<int>(lights.directional.size()), static_cast<int>(lights.points.size()), fog};
}

VariantValues variantFor(const catalog::Shader& shader, const FeatureSet& f, const VariantValues& requested) {
    VariantValues values;
    for (const auto& axis : shader.axes) {
        std::string value;
        bool asked = false;
        for (const auto& [n, v] : requested)
            if (n == axis.name) {
                value = v;
                asked = true;
            }
        if (!asked) {
            if (axis.name == "DIRECTIONAL_LIGHTS")
                value = smallestHolding(shader, axis, f.directionalLights);
            else if (axis.name == "POINT_LIGHTS")
                value = smallestHolding(shader, axis, f.pointLights);
            else if (axis.name == "FOG")
                value = f.fog ? "1" : "0";
            else
                value = axis.values.empty() ? std::string() : std::string(axis.values[0]);
        }
        values.emplace_back(std::string(axis.name), value);
    }
    for (const auto& [n, v] : requested) {  // a name that is no axis: let the cache report it
        bool known = false;
        for (const auto& axis : shader.axes) known = known || axis.name == n;
        if (!known) values.emplace_back(n, v);
    }
    return values;
}

}  // namespace prism::render
