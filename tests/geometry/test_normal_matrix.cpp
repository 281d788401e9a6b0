// Tests of the normal matrix: rotations, non-uniform scale (normals stay
// perpendicular to the transformed surface), mirrors, singular and broken matrices.
#include "prism/geometry/normal_matrix.hpp"
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"

#include "mesh_checks.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <limits>

namespace prism::geometry {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool isFinite(const glm::mat3& m) {
    for (int c = 0; c < 3; ++c)
        if (!testing::isFinite(m[c])) return false;
    return true;
}

void expectMatrixNear(const glm::mat3& actual, const glm::mat3& expected, float tolerance) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            EXPECT_NEAR(actual[c][r], expected[c][r], tolerance) << "column " << c << " row " << r;
}

glm::mat4 rotation(float degrees, glm::vec3 axis) {
    return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), axis);
}
glm::mat4 scale(glm::vec3 s) {
    return glm::scale(glm::mat4(1.0f), s);
}

TEST(NormalMatrix, RotationGivesTheRotationBackAndIgnoresTranslation) {
    const glm::mat4 world = glm::translate(glm::mat4(1.0f), {5, -3, 2}) * rotation(37.0f, {1, 2, 3});
    const NormalMatrix n = computeNormalMatrix(world);
    EXPECT_EQ(n.kind, NormalMatrixKind::Regular);
    expectMatrixNear(n.matrix, glm::mat3(world), 1e-6f);
    expectMatrixNear(normalMatrix(glm::mat4(1.0f)), glm::mat3(1.0f), 0.0f);
}

TEST(NormalMatrix, UniformScaleDoesNotChangeIt) {
    const glm::mat4 r = rotation(-71.0f, {0, 1, 1});
    for (float s : {1e-6f, 0.5f, 3.0f, 1e6f})
        expectMatrixNear(normalMatrix(r * scale(glm::vec3(s))), glm::mat3(r), 1e-5f);
}

TEST(NormalMatrix, PointsTheSameWayAsTheInverseTranspose) {
    const glm::mat4 world = rotation(20.0f, {1, 0, 0}) * scale({2, 0.5f, 7}) * rotation(-50.0f, {0, 1, 1});
    const glm::mat3 expected = glm::inverseTranspose(glm::mat3(world));
    const glm::mat3 actual = normalMatrix(world);
    for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.3f, -0.5f, 0.8f)}) {
        const glm::vec3 a = glm::normalize(actual * n), e = glm::normalize(expected * n);
        EXPECT_GT(glm::dot(a, e), 0.999999f);
    }
}

// The sphere scaled (1, 4, 1): transform positions with M and face normals with N;
// each transformed normal must be perpendicular to the transformed triangle's edges
// and point outward.
TEST(NormalMatrix, NonUniformScaleKeepsNormalsPerpendicularToTheSurface) {
    const glm::mat4 world = rotation(30.0f, {0, 0, 1}) * scale({1, 4, 1});
    const glm::mat3 linear(world);
    const glm::mat3 n = normalMatrix(world);
    const Mesh sphere = makeIcosphere(1.0f, 3);
    const std::vector<glm::vec3> faces = faceNormals(sphere);
    double worstCosine = 0.0;
    for (std::size_t t = 0; t < faces.size(); ++t) {
        const glm::vec3 a = linear * sphere.positions[sphere.indices[3 * t]];
        const glm::vec3 b = linear * sphere.positions[sphere.indices[3 * t + 1]];
        const glm::vec3 c = linear * sphere.positions[sphere.indices[3 * t + 2]];
        const glm::vec3 transformed = transformNormal(n, faces[t]);
        worstCosine = std::max(worstCosine, double(std::abs(glm::dot(transformed, glm::normalize(b - a)))));
        worstCosine = std::max(worstCosine, double(std::abs(glm::dot(transformed, glm::normalize(c - a)))));
        EXPECT_GT(glm::dot(transformed, a + b + c), 0.0f);  // outward
    }
    EXPECT_LT(worstCosine, 1e-5);
    // The naive choice (the world matrix itself) is visibly wrong for this scale.
    const glm::vec3 diagonal = glm::normalize(glm::vec3(1, 1, 0));
    const glm::vec3 tangent = linear * glm::vec3(1, -1, 0);
    EXPECT_GT(std::abs(glm::dot(glm::normalize(linear * diagonal), glm::normalize(tangent))), 0.5f);
    EXPECT_LT(std::abs(glm::dot(transformNormal(n, diagonal), glm::normalize(tangent))), 1e-6f);
}

TEST(NormalMatrix, MirrorKeepsOutwardNormalsOutward) {
    const glm::mat4 mirror = scale({-1, 1, 1}) * rotation(10.0f, {0, 1, 0});
    const glm::mat3 n = normalMatrix(mirror);
    const Mesh sphere = makeIcosphere(1.0f, 1);
    for (std::size_t i = 0; i < sphere.positions.size(); ++i)
        EXPECT_GT(glm::dot(transformNormal(n, sphere.normals[i]), glm::mat3(mirror) * sphere.positions[i]), 0.99f);
}

TEST(NormalMatrix, ZeroScaleFlattensOntoThePlaneNormal) {
    const glm::mat4 flat = rotation(25.0f, {1, 0, 0}) * scale({1, 0, 1});
    const NormalMatrix n = computeNormalMatrix(flat);
    EXPECT_EQ(n.kind, NormalMatrixKind::FlattenedPlane);
    ASSERT_TRUE(isFinite(n.matrix));
    const glm::vec3 planeNormal = glm::mat3(rotation(25.0f, {1, 0, 0})) * glm::vec3(0, 1, 0);
    // The top of a flattened sphere faces the plane normal; its bottom faces away.
    EXPECT_GT(glm::dot(transformNormal(n.matrix, glm::normalize(glm::vec3(0.3f, 1, 0.2f))), planeNormal), 0.99999f);
    EXPECT_LT(glm::dot(transformNormal(n.matrix, glm::vec3(0, -1, 0)), planeNormal), -0.99999f);
    // A normal lying in the plane has no image direction: the fallback, never NaN.
    EXPECT_EQ(transformNormal(n.matrix, {1, 0, 0}, {0, 0, 1}), glm::vec3(0, 0, 1));
}

TEST(NormalMatrix, RankOneZeroAndNonFiniteMatricesGiveTheIdentity) {
    const glm::mat4 cases[] = {
        scale({0, 0, 0}),
        scale({0, 0, 5}),
        glm::mat4(glm::vec4(1, 1, 1, 0), glm::vec4(2, 2, 2, 0), glm::vec4(-1, -1, -1, 0), glm::vec4(0, 0, 0, 1)),
        scale({1, kNaN, 1}),
        scale({kInf, 1, 1}),
        rotation(30.0f, {0, 1, 0}) * scale({1, 1, -kInf}),
    };
    for (const glm::mat4& world : cases) {
        const NormalMatrix n = computeNormalMatrix(world);
        EXPECT_EQ(n.kind, NormalMatrixKind::IdentityFallback);
        expectMatrixNear(n.matrix, glm::mat3(1.0f), 0.0f);
    }
}

TEST(NormalMatrix, ExtremeScalesNeverGiveNaNOrInf) {
    const float scales[] = {1e-38f, 1e-30f, 1e-6f, 1.0f, 1e6f, 1e30f, 3e38f};
    const glm::mat4 r = rotation(33.0f, {1, -1, 2});
    for (float sx : scales) {
        for (float sy : scales) {
            const NormalMatrix n = computeNormalMatrix(r * scale({sx, sy, 1.0f}));
            ASSERT_TRUE(isFinite(n.matrix)) << sx << " " << sy;
            EXPECT_NE(n.kind, NormalMatrixKind::IdentityFallback) << sx << " " << sy;
            for (const glm::vec3 normal : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.6f, 0.0f, 0.8f)}) {
                const glm::vec3 transformed = transformNormal(n.matrix, normal);
                EXPECT_TRUE(testing::isFinite(transformed));
                EXPECT_NEAR(glm::length(transformed), 1.0f, 1e-5f);
            }
        }
    }
}

TEST(NormalMatrix, TinyAndHugeScalesGiveTheRightDirections) {
    // Per-axis scales 1e-6..1e6 on top of an overall 1e-30, 1 or 1e30.
    const float axisScales[] = {1e-6f, 1e-3f, 1.0f, 1e3f, 1e6f};
    const glm::mat4 r = rotation(33.0f, {1, -1, 2});
    for (float overall : {1e-30f, 1.0f, 1e30f}) {
        for (float sx : axisScales) {
            for (float sy : axisScales) {
                const glm::vec3 s(sx * overall, sy * overall, overall);
                const NormalMatrix n = computeNormalMatrix(r * scale(s));
                ASSERT_TRUE(isFinite(n.matrix));
                EXPECT_EQ(n.kind, NormalMatrixKind::Regular);
                for (const glm::vec3 normal : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.6f, 0.0f, 0.8f)}) {
                    // Expected in double: R * diag(1/sx, 1/sy, 1/sz) * normal.
                    const glm::dvec3 inverseScaled = glm::dvec3(normal) / glm::dvec3(s);
                    const glm::dvec3 expected = glm::dmat3(glm::mat3(r)) * glm::normalize(inverseScaled);
                    const glm::vec3 actual = transformNormal(n.matrix, normal);
                    EXPECT_GT(glm::dot(glm::dvec3(actual), expected), 0.99999) << s.x << " " << s.y << " " << s.z;
                }
            }
        }
    }
}

TEST(NormalMatrix, TransformNormalNeverReturnsNaN) {
    EXPECT_EQ(transformNormal(glm::mat3(0.0f), {0, 1, 0}), glm::vec3(0, 0, 1));
    EXPECT_EQ(transformNormal(glm::mat3(1.0f), {kNaN, 1, 0}), glm::vec3(0, 0, 1));
    EXPECT_EQ(transformNormal(glm::mat3(1.0f), {0, 0, 0}, {1, 0, 0}), glm::vec3(1, 0, 0));
    EXPECT_EQ(transformNormal(glm::mat3(kInf), {0, 1, 0}), glm::vec3(0, 0, 1));
    EXPECT_EQ(transformNormal(glm::mat3(2.0f), {0, 3, 0}), glm::vec3(0, 1, 0));
}

}  // namespace
}  // namespace prism::geometry
