// The usage example of prism/diffraction/diffraction_gl.hpp, compiled and run by tests/snippets
// (needs a GL 4.3 context, headless).
#include "prism/gl/gl.hpp"
#include "prism/gl/gl_context.hpp"
// [snippet]
#include "prism/diffraction/diffraction_gl.hpp"
using namespace prism::diffraction;
// [/snippet]

int main() {
    auto context = prism::gl::createContext({.majorVersion = 4, .minorVersion = 3});
    // [snippet]
    StamBrdf brdf(sinusoidGrating({.amplitudeNm = 60, .periods = 16}), {.tolerance = 1e-4});
    DiffractionTextures textures(buildSpectralTables(brdf, {.size = 32}));  // path (a)
    prism::gl::Program& program = diffractionPrograms().get("brdf_map", {{"DIFFRACTION_PATH", textures.variant()}});
    textures.apply(program);  // binds units 0 and 1, sets u_diffraction*
    // [/snippet]
    prism::gl::throwIfGlError("the diffraction example");
    return !textures.integrated() && textures.bytes() > 0 ? 0 : 1;
}
