// The usage example of prism/catalog/line_directive.hpp, compiled and run by
// tests/snippets: one `#line` rule for every GLSL version.
#include <string>

// [snippet]
#include "prism/catalog/line_directive.hpp"
// [/snippet]

int main() {
    // [snippet]
    const auto version = prism::catalog::glslVersionOf("#version 300 es");
    // make the next line line 12 of source string 2:
    std::string directive = prism::catalog::lineDirective(12, 2, version);  // "#line 12 2"
    // [/snippet]
    const bool esOk = directive == "#line 12 2";
    const bool oldOk =
        prism::catalog::lineDirective(12, 2, prism::catalog::glslVersionOf("#version 150")) == "#line 11 2";
    return esOk && oldOk ? 0 : 1;
}
