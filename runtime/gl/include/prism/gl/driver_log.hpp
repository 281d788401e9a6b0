// Translation of GL driver compile logs into GCC-style `file:line:column:` messages
// through a stage's source-number table (the `#line L N` numbering).
//
// Usage (snippet: examples/snippets/gl_driver_log.cpp):
//
//     #include <vector>
//
//     #include "prism/gl/driver_log.hpp"
//     std::vector<prism::gl::SourceName> files{{0, "shaders/phong.frag"}, {1, "modules/lights.glsl"}};
//     std::string nice = prism::gl::translateDriverLog(log, files);
//     // "1:12(3): error: `foo' undeclared"  ->  "modules/lights.glsl:12:3: error: `foo' undeclared"
//
// Understood line shapes: Mesa `N:L(C): ...`, NVIDIA `N(L) : ...` and AMD/glslang
// `ERROR: N:L: ...`. Lines of any other shape, and lines whose source number is not
// in the table, are kept unchanged. Columns are passed on as the driver counts them
// (Mesa's may point a little before the offending token).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace prism::gl {

// One row of a stage's line table: source number `number` is file `path`.
struct SourceName {
    std::uint32_t number = 0;
    std::string path;
};

std::string translateDriverLog(std::string_view log, std::span<const SourceName> files);

}  // namespace prism::gl
