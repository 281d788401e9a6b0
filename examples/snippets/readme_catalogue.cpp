// The C++ example of README.md ("Using it from CMake"), compiled and run by tests/snippets.
#include <string>

// [snippet]
#include "prism/shaders.hpp"
// [/snippet]

int main() {
    // [snippet]
    const auto& phong = prism::shaders::shaderInfo(prism::shaders::ShaderId::phong);
    std::string vertexSource = prism::catalog::joinChunks(phong.variants[0].stages[0].chunks);
    // [/snippet]
    return vertexSource.rfind("#version", 0) == 0 && vertexSource.find("#include") == std::string::npos ? 0 : 1;
}
