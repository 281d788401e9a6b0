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
//     cache.size();   // programs built so far
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

  private:
    const catalog::Catalog& catalog_;
    std::map<std::pair<std::string, std::string>, std::unique_ptr<gl::Program>> programs_;
};

}  // namespace prism::render
