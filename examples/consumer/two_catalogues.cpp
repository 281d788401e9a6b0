// Example consumer: a catalogue built with no NAMESPACE (toon_shaders, its target's name)
// and Prism's own (prism::shaders, in libprism_shaders) in one program. Each kCatalog is
// its own symbol; were the default still prism::shaders, this file would not compile (two
// ShaderId enums in one namespace) or, without the headers, link to one of the two.
// tests/integration/installed_runtime.sh runs it.
#include <iostream>

#include "prism/shaders.hpp"
#include "toon_shaders.hpp"

int main() {
    const prism::catalog::Catalog& mine = toon_shaders::kCatalog;
    const prism::catalog::Catalog& prisms = prism::shaders::kCatalog;
    const bool ok = &mine != &prisms && prism::catalog::findShader(mine, "toon") != nullptr &&
                    prism::catalog::findShader(mine, "phong") == nullptr &&
                    prism::catalog::findShader(prisms, "phong") != nullptr &&
                    prism::catalog::findShader(prisms, "toon") == nullptr;
    std::cout << "toon_shaders: " << mine.shaders.size() << " shader(s); prism::shaders: " << prisms.shaders.size()
              << " shader(s)\n";
    std::cout << (ok ? "two catalogues: OK" : "two catalogues: one symbol for both") << '\n';
    return ok ? 0 : 1;
}
