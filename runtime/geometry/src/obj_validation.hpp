// Internal: a light line-by-line check of OBJ text that finds the first malformed
// `v`/`vt`/`vn`/`f` line before tinyobjloader (which would read a bad number as 0
// and drop a face with a bad index silently). Not installed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace prism::geometry::detail {

// Prism's limit on the corners of one `f` polygon (docs/reliability.md).
inline constexpr std::size_t kMaxFaceCorners = 4096;

struct ObjProblem {
    std::size_t line;  // 1-based
    std::string message;
};

// The first problem in `text`, or nothing. Checks: `v` has 3 (x y z), 4 (+w) or 6
// (+r g b) finite numbers; `vn` 3; `vt` 1 to 3; `f` has >= 3 corners of the form
// v, v/vt, v//vn or v/vt/vn (at most kMaxFaceCorners) with integer indices that are not 0 and refer to an
// existing element (positive: 1..count in the file; negative: relative, back from
// the elements defined so far). Other statements are left to tinyobjloader.
std::optional<ObjProblem> findFirstObjProblem(std::string_view text);

}  // namespace prism::geometry::detail
