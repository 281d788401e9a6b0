// Which catalogue program the viewer's catalogue view runs: the variant derived from its
// lights and fog (prism/render/feature_variants.hpp) with the axis values picked in the
// catalogue panel on top, and which picks are valid (the panel greys out the others).
//
//     VariantValues v = effectiveVariant(phong, features, {{"BLINN", "1"}});
//     bool ok = isValidChoice(phong, v, "DIRECTIONAL_LIGHTS", "4");   // a generated variant?
//     std::string label = variantLabel(v);                            // "BLINN=1,FOG=0,..."
#pragma once

#include <string>
#include <string_view>

#include "prism/catalog/shader_catalog.hpp"
#include "prism/render/feature_variants.hpp"

namespace prism::viewer {

// The full axis values the view runs; picks for axes `shader` lacks are dropped, and a
// combination the catalogue did not generate falls back to the derived one.
render::VariantValues effectiveVariant(const catalog::Shader& shader, const render::FeatureSet& features,
                                       const render::VariantValues& picks);

// Whether `current` with `axis` set to `value` is a generated variant of `shader`.
bool isValidChoice(const catalog::Shader& shader, const render::VariantValues& current, std::string_view axis,
                   std::string_view value);

// Sets (or adds) `axis` = `value` in `values`.
void setAxis(render::VariantValues& values, std::string_view axis, std::string_view value);

std::string variantLabel(const render::VariantValues& values);

// Why `picks` name no generated variant of `shader` with these features (an axis it lacks,
// a value the axis lacks, or a combination the catalogue lacks), or empty when they do.
// The command line and scripts reject such picks instead of falling back silently.
std::string whyNotAVariant(const catalog::Shader& shader, const render::FeatureSet& features,
                           const render::VariantValues& picks);

}  // namespace prism::viewer
