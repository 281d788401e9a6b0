// Part of the es300 target (es300_target.hpp): the static check of one linked ES 3.00
// program against the minimum limits every ES 3.00 device must give (GLSL ES 3.00 §7.3
// built-in constants). A phone may give no more; a desktop browser's SwiftShader reports
// far more, so a browser test cannot find a program over them. Over a limit is a warning
// at the stage file that uses too much (the vertex stage's for its uniforms, texture units
// and outputs; the fragment stage's for its own), naming the program, the limit and the count.
//
// Counting rule (stated in docs/targets.md): the packing algorithm of the GLSL ES spec
// (GLSL ES 1.00 Appendix A §7, which ES 3.00's limits refer to), applied per stage to the
// active uniforms (glslang's reflection) and to the vertex stage's declared outputs: a
// matCxR element takes C rows of R components; rows of 4 and 3 components take a row each;
// two 2-component rows share a row; scalars fill the free column of the 3-component rows,
// then the free half of an odd 2-component row, then rows of 4. Samplers count texture units.
//
//   const auto check =
//       es300LimitsCheck("phong (variant BLINN=1)", {"shader_sources/phong.vert", "shader_sources/phong.frag"});
//   validateProgram(esStages, contract, check);  // warnings over a limit, among the diagnostics
#pragma once

#include <string>
#include <vector>

#include "validator.hpp"

namespace prism::shaderc {

struct Es300Limits {
    int vertexUniformVectors = 256;    // GL_MAX_VERTEX_UNIFORM_VECTORS
    int fragmentUniformVectors = 224;  // GL_MAX_FRAGMENT_UNIFORM_VECTORS
    int varyingVectors = 15;           // GL_MAX_VARYING_VECTORS (16 vec4 of outputs, 15 guaranteed usable)
    int textureUnits = 16;             // GL_MAX_TEXTURE_IMAGE_UNITS, and vertex texture units
};

// One element of a uniform or varying: `rows` rows of `columns` components each.
struct PackedShape {
    int rows = 1;
    int columns = 4;
    int count = 1;  // array elements
};

// Rows of vec4 that the shapes take under the packing rule above.
int packedRows(const std::vector<PackedShape>& shapes);

// The shape of a GLSL type spelled as stage_interface.hpp spells it ("vec3", "mat4x2"); a
// struct or unknown type counts as one full row per element.
PackedShape shapeOfGlslType(const std::string& type, int arraySize);

struct Es300Usage {
    int vertexUniformVectors = 0, fragmentUniformVectors = 0, varyingVectors = 0;
    int vertexTextureUnits = 0, fragmentTextureUnits = 0;
};

// The files of a program's two stages, where its warnings point.
struct Es300StagePaths {
    std::string vertex, fragment;
};

// The warnings of a program using `usage`, each at the file of the stage that uses too much.
std::vector<Diagnostic> limitWarnings(const std::string& program, const Es300StagePaths& paths, const Es300Usage& usage,
                                      const Es300Limits& limits = {});

// The check validateProgram runs on the linked ES program: measures it and warns.
LinkedProgramCheck es300LimitsCheck(const std::string& program, const Es300StagePaths& paths);

}  // namespace prism::shaderc
