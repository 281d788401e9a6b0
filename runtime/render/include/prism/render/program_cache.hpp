// Programs built from a generated catalogue on first use and shared afterwards, keyed
// by shader and variant: two draws with the same shader and feature set share one
// program.
//
// Usage (snippet: examples/snippets/render_program_cache.cpp):
//
//     #include "prism/render/program_cache.hpp"
//     #include "prism/shaders.hpp"
//     prism::render::ProgramCache cache(prism::shaders::kCatalog);
//     prism::gl::Program& p = cache.get("phong", {{"BLINN", "1"}});
//     cache.size();  // programs built so far
//
//     // Hot reload (prism/render/shader_watcher.hpp does this on a file edit): swap in a
//     // program rebuilt from edited sources. References from get() stay valid and name
//     // the new program from now on.
//     const prism::catalog::Variant& blinn = cache.variantOf("phong", {{"BLINN", "1"}});
//     prism::gl::Program rebuilt(blinn, prism::shaders::kCatalog.contractAttributes, "phong");
//     cache.reload("phong", blinn.name, std::move(rebuilt));
//
// get() throws prism::render::UnknownShaderError listing the known shaders (or the shader's
// variants) when the name or the variant does not exist. Needs a current context.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "prism/gl/program.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::render {

using VariantValues = std::vector<std::pair<std::string, std::string>>;

class UnknownShaderError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

class ProgramCache {
  public:
    explicit ProgramCache(const catalog::Catalog& catalog) : catalog_(catalog) {}

    gl::Program& get(std::string_view shader, const VariantValues& variant = {});
    std::size_t size() const { return programs_.size(); }
    const catalog::Catalog& catalog() const { return catalog_; }

    // The variant `get` would use; throws UnknownShaderError like get().
    const catalog::Variant& variantOf(std::string_view shader, const VariantValues& variant) const;
    std::vector<std::string> shaderNames() const;

    // Replaces the program of `shader`'s variant named `variantName` (the catalogue's
    // Variant::name, e.g. "BLINN=1,FOG=0,DIRECTIONAL_LIGHTS=1,POINT_LIGHTS=0", or
    // "default") with `program`, whether or not it was built before. The old program is
    // deleted; a reference returned by get() now names the new one. Throws
    // UnknownShaderError for a shader or variant name the catalogue lacks.
    void reload(std::string_view shader, std::string_view variantName, gl::Program program);
    // The names of `shader`'s variants that have a program now (built or reloaded).
    std::vector<std::string> builtVariants(std::string_view shader) const;
    // How many programs reload() has swapped in since construction.
    std::size_t reloadCount() const { return reloads_; }

  private:
    const catalog::Catalog& catalog_;
    std::map<std::pair<std::string, std::string>, std::unique_ptr<gl::Program>> programs_;
    std::size_t reloads_ = 0;
};

}  // namespace prism::render
