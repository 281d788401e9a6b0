// The rain system's programs: a render::ProgramCache over the rain catalogue
// (prism/rain_shaders.hpp, built from shader_sources/rain against modules/ and the
// two contracts) that also records which programs were asked for, so a test can show
// which programs a scene uses (e.g. none of the rain ones without rain, no FOG=1
// variant without fog).
//
// Usage (snippet: examples/snippets/rain_rain_programs.cpp):
//
//     #include "prism/rain/rain_programs.hpp"
//     prism::rain::RainPrograms programs;
//     prism::gl::Program& p = programs.get("ground", {{"FOG", "0"}});
//     programs.used();  // {"ground (FOG=0)"}
//
// Programs are built on first use (needs a current context).
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "prism/render/program_cache.hpp"
#include "prism/catalog/shader_catalog.hpp"

namespace prism::rain {

const catalog::Catalog& rainCatalog();

class RainPrograms {
  public:
    RainPrograms();
    gl::Program& get(std::string_view shader, const render::VariantValues& variant = {});
    // "shader (variant name)" of every program asked for, sorted.
    std::vector<std::string> used() const { return {used_.begin(), used_.end()}; }
    std::size_t built() const { return cache_.size(); }
    render::ProgramCache& cache() { return cache_; }
    const catalog::Catalog& catalog() const { return cache_.catalog(); }

  private:
    render::ProgramCache cache_;
    std::set<std::string> used_;
};

}  // namespace prism::rain
