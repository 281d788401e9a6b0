// The normal matrix through the cofactor matrix, with the fallbacks documented in
// prism/geometry/normal_matrix.hpp. All arithmetic in double.
#include "prism/geometry/normal_matrix.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace prism::geometry {

namespace {

// Below this |det| / (|a0| |a1| |a2|) the columns do not span a volume we can trust.
constexpr double kSingularVolumeRatio = 1e-12;
// Below this sin(angle) between every pair of columns the matrix has rank <= 1.
constexpr double kRankOneSine = 1e-12;
// Results with an entry beyond this are divided by their largest entry, so that a
// shader's normalize(N * n) cannot overflow float while squaring (1e18^2 * 3 < 3.4e38).
constexpr double kLargestSafeEntry = 1e18;
// transformNormal: a result shorter than this times the sum of the lengths of its parts
// (|n_i| * |column i|) has cancelled out and has no direction.
constexpr double kVanishingNormalRatio = 1e-6;

bool isFinite(const glm::mat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

double largestEntry(const glm::dmat3& m) {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(m[c][r]));
    return largest;
}

glm::mat3 toFloatKeepingDirection(glm::dmat3 m) {
    const double largest = largestEntry(m);
    if (largest > kLargestSafeEntry) m /= largest;
    return glm::mat3(m);
}

}  // namespace

NormalMatrix computeNormalMatrix(const glm::mat3& linearPart) {
    if (!isFinite(linearPart)) return {glm::mat3(1.0f), NormalMatrixKind::IdentityFallback};

    const glm::dmat3 a(linearPart);
    // Columns of cof(A) = det(A) * inverse(A)^T are the cross products of A's columns.
    const glm::dmat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
    const double determinant = glm::dot(a[0], cofactor[0]);
    const double length0 = glm::length(a[0]), length1 = glm::length(a[1]), length2 = glm::length(a[2]);

    const double columnVolume = length0 * length1 * length2;
    if (columnVolume > 0.0 && std::abs(determinant) > kSingularVolumeRatio * columnVolume) {
        const double scale = std::copysign(1.0, determinant) / std::cbrt(determinant * determinant);
        return {toFloatKeepingDirection(cofactor * scale), NormalMatrixKind::Regular};
    }

    // Singular: rank 2 if some pair of columns is independent.
    const double pairSines[3] = {
        glm::length(cofactor[0]) / (length1 * length2),  // a1 x a2
        glm::length(cofactor[1]) / (length2 * length0),  // a2 x a0
        glm::length(cofactor[2]) / (length0 * length1),  // a0 x a1
    };
    bool rankTwo = false;
    for (double sine : pairSines) rankTwo = rankTwo || (std::isfinite(sine) && sine > kRankOneSine);
    if (!rankTwo) return {glm::mat3(1.0f), NormalMatrixKind::IdentityFallback};
    return {glm::mat3(cofactor / largestEntry(cofactor)), NormalMatrixKind::FlattenedPlane};
}

NormalMatrix computeNormalMatrix(const glm::mat4& world) {
    return computeNormalMatrix(glm::mat3(world));
}

glm::vec3 transformNormal(const glm::mat3& normalMatrix, const glm::vec3& normal, const glm::vec3& fallback) {
    const glm::dmat3 n(normalMatrix);
    const glm::dvec3 v(normal);
    const glm::dvec3 transformed = n * v;
    double partsLength = 0.0;  // |n_0| |column 0| + |n_1| |column 1| + |n_2| |column 2|
    for (int c = 0; c < 3; ++c) partsLength += std::abs(v[c]) * glm::length(n[c]);
    const double length = glm::length(transformed);
    if (!std::isfinite(length) || !std::isfinite(partsLength) || !(length > 0.0) ||
        !(length > kVanishingNormalRatio * partsLength))
        return fallback;
    return glm::vec3(transformed / length);
}

}  // namespace prism::geometry
