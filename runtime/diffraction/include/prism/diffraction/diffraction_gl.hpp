// The GL side of the diffraction shader: uploads the lookup tables of one path (and nothing
// for the other) and sets modules/diffraction/stam.glsl's uniforms on a program from the
// diffraction catalogue (prism/diffraction_shaders.hpp). The only file of prism_diffraction
// that calls GL.
//
// Usage (snippet: examples/snippets/diffraction_diffraction_gl.cpp):
//
//     #include "prism/diffraction/diffraction_gl.hpp"
//     using namespace prism::diffraction;
//     StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
//     DiffractionTextures textures(buildSpectralTables(brdf, {.size = 32}));  // path (a)
//     prism::gl::Program& program = diffractionPrograms().get("brdf_map", {{"DIFFRACTION_PATH", textures.variant()}});
//     textures.apply(program);  // binds units 0 and 1, sets u_diffraction*
//
// Needs a current context for its whole life; move-only.
#pragma once

#include <cstddef>

#include "prism/diffraction/lookup_tables.hpp"
#include "prism/gl/program.hpp"
#include "prism/gl/handles.hpp"
#include "prism/render/program_cache.hpp"

namespace prism::diffraction {

class DiffractionTextures {
  public:
    explicit DiffractionTextures(const SpectralTables& tables);    // path (a): RG32F layers + wavelengths
    explicit DiffractionTextures(const IntegratedTables& tables);  // path (b): RGB32F layers
    explicit DiffractionTextures(const VolumeTables& tables);      // path (c): RGB32F 3D texture
    DiffractionTextures(DiffractionTextures&& other) noexcept = default;
    DiffractionTextures& operator=(DiffractionTextures&& other) noexcept = default;
    DiffractionTextures(const DiffractionTextures&) = delete;
    DiffractionTextures& operator=(const DiffractionTextures&) = delete;

    bool integrated() const { return uniforms_.path != 0; }
    // The DIFFRACTION_PATH variant value these tables need: "0" (a), "1" (b) or "2" (c).
    const char* variant() const { return uniforms_.variant(); }
    std::size_t bytes() const { return bytes_; }  // GPU memory of the tables
    // Binds the tables to texture unit `unit` (and the wavelengths to unit + 1 on path a) and
    // sets the program's u_diffraction* uniforms.
    void apply(gl::Program& program, int unit = 0) const;

  private:
    TableUniforms uniforms_;
    gl::Texture tables_, wavelengths_;
    std::size_t bytes_ = 0;
};

// The diffraction catalogue's programs (built on first use; needs a current context).
render::ProgramCache& diffractionPrograms();

}  // namespace prism::diffraction
