// The usage example of prism/geometry/obj_loader.hpp, compiled and run by tests/snippets.
// It writes a small OBJ file (a quad and a triangle) as monkey.obj first.
#include <fstream>

// [snippet]
#include <iostream>

#include "prism/geometry/obj_loader.hpp"
using namespace prism::geometry;
// [/snippet]

int main() {
    std::ofstream("monkey.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nf 1 2 3 4\nf 1 2 5\n";
    const char* path = "missing.obj";
    // [snippet]
    Mesh split = loadObj("monkey.obj");  // one vertex per face corner
    ObjLoadOptions smooth;
    smooth.weld = true;                 // merge by position
    smooth.creaseAngleDegrees = 60.0f;  // but keep sharp edges
    Mesh mesh = loadObj("monkey.obj", smooth);
    try {
        loadObj(path);
    } catch (const ObjLoadError& e) {
        std::cerr << e.what();
    }
    // [/snippet]
    return split.positions.size() == 9 && mesh.positions.size() < split.positions.size() ? 0 : 1;
}
