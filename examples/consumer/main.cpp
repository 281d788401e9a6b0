// Example consumer of Prism: lists what the two generated catalogues hold (shader and
// module names and counts): names and counts from the small generated headers, at
// compile time; the rest from the data each catalogue target compiles in. No GL.
#include <cstddef>
#include <iostream>
#include <string_view>

#include "consumer/lit_shaders.hpp"
#include "consumer/plain_shaders.hpp"

namespace {

void printCatalog(std::string_view title, const prism::catalog::Catalog& catalog) {
    std::cout << title << ": " << catalog.shaders.size() << " shaders, " << catalog.modules.size() << " modules\n";
    for (const auto& shader : catalog.shaders) {
        std::cout << "  shader " << shader.name << ": " << shader.variants.size() << " variant(s), modules:";
        for (auto m : shader.modules) std::cout << ' ' << catalog.modules[m].name;
        std::cout << '\n';
    }
    for (const auto& module : catalog.modules)
        std::cout << "  module " << module.name << ": " << module.description << '\n';
}

}  // namespace

int main() {
    // Named ids: this file no longer compiles when a shader is renamed or removed.
    constexpr auto phong = consumer::lit::ShaderId::tinted_phong;
    constexpr auto checker = consumer::plain::ShaderId::checker;
    static_assert(consumer::lit::name(phong) == "tinted_phong");
    static_assert(consumer::plain::moduleIdFromName("checker").has_value());
    if (consumer::lit::kShaderCount != consumer::lit::kCatalog.shaders.size() ||
        consumer::plain::kModuleCount != consumer::plain::kCatalog.modules.size()) {
        std::cerr << "a generated header and its data file disagree\n";
        return 1;
    }

    printCatalog("lit_shaders", consumer::lit::kCatalog);
    printCatalog("plain_shaders", consumer::plain::kCatalog);

    // The tint is the lit catalogue's own module; the plain catalogue must not use it.
    bool ok = consumer::lit::moduleIdFromName("tint").has_value() &&
              consumer::plain::moduleIdFromName("checker").has_value() &&
              !consumer::plain::moduleIdFromName("tint").has_value();
    std::cout << "lit shader: " << consumer::lit::name(phong) << ", plain shader: " << consumer::plain::name(checker)
              << '\n';
    std::cout << (ok ? "consumer: OK" : "consumer: unexpected catalogue contents") << '\n';
    return ok ? 0 : 1;
}
