// Wavefront OBJ import (through tinyobjloader) into a prism::geometry::Mesh, with
// errors that name the file and line.
//
// Usage (snippet: examples/snippets/geometry_obj_loader.cpp):
//
//     #include <iostream>
//
//     #include "prism/geometry/obj_loader.hpp"
//     using namespace prism::geometry;
//     Mesh split = loadObj("monkey.obj");  // one vertex per face corner
//     ObjLoadOptions smooth;
//     smooth.weld = true;                 // merge by position
//     smooth.creaseAngleDegrees = 60.0f;  // but keep sharp edges
//     Mesh mesh = loadObj("monkey.obj", smooth);
//     try {
//         loadObj(path);
//     } catch (const ObjLoadError& e) {
//         std::cerr << e.what();
//     }
//
// What you get: every polygon triangulated (quads along the shorter diagonal), all
// shapes/groups merged into one mesh, vertices split per face corner (as in the file),
// positions, uvs if every corner has one, and normals: the file's if every corner has
// one (and useFileNormals), else computed (flat face normals, since nothing is shared).
// With `weld`, vertices are merged by position (see prism/geometry/weld.hpp) and normals are
// recomputed area-weighted; uv seams are kept. Materials are ignored.
//
// Errors (ObjLoadError, a std::runtime_error), GCC style:
//     path: error: cannot open the file (No such file or directory); check the path ...
//     path:12: error: `v` needs 3 numeric coordinates, got 'abc'
//     path:40: error: face index 9 is out of range: the file defines 8 positions
// The file is pre-validated line by line before tinyobjloader parses it, because
// tinyobjloader turns a bad number into 0 and skips faces with bad indices silently.
#pragma once

#include "prism/geometry/mesh.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace prism::geometry {

struct ObjLoadOptions {
    bool weld = false;
    std::optional<float> creaseAngleDegrees;  // only with weld; nullopt = merge by position alone
    bool useFileNormals = true;               // without weld: keep `vn` normals if complete
};

class ObjLoadError : public std::runtime_error {
  public:
    ObjLoadError(std::filesystem::path file, std::size_t line, const std::string& message);

    const std::filesystem::path& file() const { return file_; }
    std::size_t line() const { return line_; }  // 1-based; 0 when not about one line

  private:
    std::filesystem::path file_;
    std::size_t line_;
};

// Loads and triangulates an OBJ file. Throws ObjLoadError.
Mesh loadObj(const std::filesystem::path& file, const ObjLoadOptions& options = {});

}  // namespace prism::geometry
