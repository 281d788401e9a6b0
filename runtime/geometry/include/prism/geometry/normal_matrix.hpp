// The normal matrix (for u_normal): how a world matrix transforms surface normals,
// computed so that it is never NaN or Inf, even for singular or broken matrices.
//
// Usage (snippet: examples/snippets/geometry_normal_matrix.cpp):
//
//     #include "prism/geometry/normal_matrix.hpp"
//     glm::mat3 n = prism::geometry::normalMatrix(world);          // upload as u_normal
//     glm::vec3 nw = prism::geometry::transformNormal(n, normal);  // unit, never NaN
//
// Normals transform with the inverse-transpose of the upper 3x3 block A of the world
// matrix (translation does not matter). We compute it through the cofactor matrix
// cof(A) = det(A) * inverse(A)^T, which exists for every A, in double:
//
//  * regular A (the columns span a volume: |det A| / (|a0| |a1| |a2|) > 1e-12):
//        N = sign(det A) * cof(A) / |det A|^(2/3)  =  |det A|^(1/3) * inverse(A)^T
//    i.e. the inverse-transpose rescaled to unit volume. It is the exact
//    inverse-transpose when |det A| = 1 (a rotation gives the rotation back), is the
//    same for A and s*A, and points normals the same way as inverse(A)^T (a mirror
//    keeps outward normals outward). Shaders normalise anyway, so only the direction
//    is meaningful; the rescaling keeps the numbers near 1 for scales from 1e-6 to 1e6
//    and beyond.
//  * singular A of rank 2 (a scale of 0 along one axis flattens the mesh into a plane):
//        N = cof(A) / max|cof(A)|
//    cof(A) then maps every normal onto the plane's normal, which is the right normal
//    of the flattened surface (orientation is undefined, so no sign is applied).
//  * rank 0 or 1 (flattened to a line or a point), or any NaN/Inf entry: the identity.
//  * Should an entry exceed 1e18 (scale ratios beyond about 1e12 between axes), the
//    result is divided by its largest entry: the direction is kept and a shader's
//    normalize(N * n) cannot overflow. Entries far below the largest (ratio beyond
//    ~1e38) may then flush to zero; no transform in practice comes near that.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace prism::geometry {

enum class NormalMatrixKind {
    Regular,          // rescaled inverse-transpose
    FlattenedPlane,   // singular, rank 2: normalised cofactor matrix
    IdentityFallback  // rank <= 1 or non-finite input
};

struct NormalMatrix {
    glm::mat3 matrix{1.0f};
    NormalMatrixKind kind = NormalMatrixKind::Regular;
};

// The normal matrix of the upper 3x3 of `world`, with how it was obtained.
NormalMatrix computeNormalMatrix(const glm::mat4& world);
NormalMatrix computeNormalMatrix(const glm::mat3& linearPart);

// Just the matrix.
inline glm::mat3 normalMatrix(const glm::mat4& world) {
    return computeNormalMatrix(world).matrix;
}

// normalMatrix * normal, normalised (in double); `fallback` when the result has no
// direction: zero, non-finite, or cancelled to below 1e-6 of the sum of its parts'
// lengths (a normal lying in a flattened plane).
glm::vec3 transformNormal(const glm::mat3& normalMatrix, const glm::vec3& normal,
                          const glm::vec3& fallback = glm::vec3(0.0f, 0.0f, 1.0f));

}  // namespace prism::geometry
