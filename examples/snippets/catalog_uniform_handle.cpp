// The usage example of prism/catalog/uniform_handle.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/catalog/uniform_handle.hpp"
// [/snippet]

// [snippet]
struct Toon {};  // a generated header's tag
constexpr prism::catalog::UniformHandle<prism::catalog::GlslType::Vec3, 4, Toon> u_lights{"u_lights"};
static_assert(u_lights.arrayLength == 4 && u_lights.type == prism::catalog::GlslType::Vec3);
static_assert(prism::catalog::glslTypeName(u_lights.type) == "vec3");
// [/snippet]

int main() {
    return u_lights.name == "u_lights" ? 0 : 1;
}
