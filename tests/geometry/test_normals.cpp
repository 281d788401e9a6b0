// Tests of face and area-weighted vertex normals: the worked example of the FUDGE shader thesis §6.2,
// degenerate input, the fallback chain and extreme scales.
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/geometry/weld.hpp"

#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <ostream>

namespace prism::geometry {
namespace {

using testing::hasUnitNormals;
using testing::isFinite;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// FUDGE shader thesis §6.2: triangle A(0,0,0) B(6,0,0) C(3,5,0) (area 15, cross
// (0,0,30)) and triangle A(0,0,0) B(0,12,0) C(0,6,10) (area 60, cross (120,0,0))
// share the vertex A; its area-weighted normal is (120,0,30) normalised.
Mesh thesisExample() {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {6, 0, 0}, {3, 5, 0}, {0, 12, 0}, {0, 6, 10}};
    mesh.indices = {0, 1, 2, 0, 3, 4};
    return mesh;
}

TEST(AreaWeightedNormals, ThesisWorkedExampleGivesTheThesisNormal) {
    const Mesh mesh = thesisExample();
    const std::vector<glm::dvec3> crosses = faceCrossProducts(mesh);
    EXPECT_EQ(crosses[0], glm::dvec3(0, 0, 30));   // twice the area 15
    EXPECT_EQ(crosses[1], glm::dvec3(120, 0, 0));  // twice the area 60

    const glm::vec3 shared = areaWeightedVertexNormals(mesh)[0];
    EXPECT_NEAR(shared.x, 0.97f, 0.005f);
    EXPECT_NEAR(shared.y, 0.0f, 1e-7f);
    EXPECT_NEAR(shared.z, 0.243f, 0.0005f);
    // Exactly (4, 0, 1) / sqrt(17), not the equal-weight (0.707, 0, 0.707).
    EXPECT_NEAR(shared.x, 4.0f / std::sqrt(17.0f), 1e-6f);
    EXPECT_NEAR(shared.z, 1.0f / std::sqrt(17.0f), 1e-6f);
}

TEST(AreaWeightedNormals, ThesisExampleImportedSplitThenWeldedGivesTheSameNormal) {
    const Mesh split = splitVerticesPerFace(thesisExample());  // as the thesis's MeshObj has it (§6.3)
    ASSERT_EQ(split.positions.size(), 6u);
    const WeldResult welded = weldVertices(split);
    ASSERT_EQ(welded.mesh.positions.size(), 5u);
    const glm::vec3 shared = welded.mesh.normals[welded.newIndexOfOldVertex[0]];
    EXPECT_NEAR(shared.x, 0.970f, 0.005f);
    EXPECT_NEAR(shared.z, 0.243f, 0.0005f);
}

TEST(AreaWeightedNormals, SingleTriangleHasItsFaceNormalAtEveryCorner) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    NormalStats stats = computeVertexNormals(mesh);
    EXPECT_EQ(stats.degenerateTriangles, 0u);
    EXPECT_EQ(stats.fallbackVertices, 0u);
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// A valid triangle facing +X plus one bad triangle whose vertices 3..5 are used
// nowhere else: they have no valid face and no neighbour with a direction, and the
// mesh as a whole faces +X, so they take +X (fallback step 2).
Mesh validPlusBad(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, a, b, c};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    return mesh;
}

struct DegenerateCase {
    const char* name;
    glm::vec3 a, b, c;
};

void PrintTo(const DegenerateCase& c, std::ostream* out) {
    *out << c.name;
}

class DegenerateTriangle : public ::testing::TestWithParam<DegenerateCase> {};

TEST_P(DegenerateTriangle, ContributesNothingAndItsVerticesGetTheFallback) {
    const DegenerateCase& c = GetParam();
    Mesh mesh = validPlusBad(c.a, c.b, c.c);
    const NormalStats stats = computeVertexNormals(mesh);
    EXPECT_EQ(stats.degenerateTriangles, 1u);
    EXPECT_EQ(stats.fallbackVertices, 3u);
    EXPECT_TRUE(hasUnitNormals(mesh));
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(1, 0, 0));
    const std::vector<glm::vec3> perFace = faceNormals(mesh);
    EXPECT_EQ(perFace[1], glm::vec3(1, 0, 0));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, DegenerateTriangle,
    ::testing::Values(DegenerateCase{"ZeroArea", {2, 2, 2}, {2, 2, 2}, {2, 2, 2}},
                      DegenerateCase{"Collinear", {0, 0, 0}, {1, 1, 1}, {2, 2, 2}},
                      // 0.3f is not exactly 3 * 0.1f: numerically, not exactly, collinear.
                      DegenerateCase{"NumericallyCollinear", {0, 0, 0}, {0.1f, 0.2f, 0.3f}, {0.3f, 0.6f, 0.9f}},
                      DegenerateCase{"HugeCollinear", {1e30f, 0, 0}, {2e30f, 1e24f, 0}, {3e30f, 2e24f, 0}},
                      DegenerateCase{"NaNCorner", {kNaN, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                      DegenerateCase{"InfCorner", {0, 0, 0}, {kInf, 0, 0}, {0, 1, 0}},
                      DegenerateCase{"NegativeInfCorner", {0, 0, 0}, {1, 0, 0}, {0, -kInf, 0}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(AreaWeightedNormals, RepeatedIndexContributesNothing) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    mesh.indices = {0, 1, 2, 3, 3, 1};
    const NormalStats stats = computeVertexNormals(mesh);
    EXPECT_EQ(stats.degenerateTriangles, 1u);
    EXPECT_EQ(mesh.normals[1], glm::vec3(0, 0, 1));
    // Vertex 3 only appears in the bad triangle; its neighbour 1 has a direction.
    EXPECT_EQ(mesh.normals[3], glm::vec3(0, 0, 1));
}

TEST(AreaWeightedNormals, NaNVertexInAGridTakesItsNeighboursDirection) {
    Mesh grid = makeGrid(2.0f, 2.0f, 4, 4);
    grid.positions[12] = {kNaN, kNaN, kNaN};  // the centre vertex (5 x 5 vertices)
    const NormalStats stats = computeVertexNormals(grid);
    EXPECT_EQ(stats.degenerateTriangles, 6u);
    EXPECT_EQ(stats.fallbackVertices, 1u);
    EXPECT_TRUE(hasUnitNormals(grid));
    for (const glm::vec3& n : grid.normals) EXPECT_NEAR(n.y, 1.0f, 1e-6f);
}

TEST(AreaWeightedNormals, AllDegenerateMeshUsesTheConfiguredFallback) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {kNaN, 0, 0}};
    mesh.indices = {0, 1, 2, 1, 2, 3};
    EXPECT_TRUE(hasUnitNormals([&] {
        Mesh m = mesh;
        computeVertexNormals(m);
        return m;
    }()));
    for (const glm::vec3& n : areaWeightedVertexNormals(mesh)) EXPECT_EQ(n, glm::vec3(0, 0, 1));

    VertexNormalOptions sideways;
    sideways.fallbackNormal = {0, 3, 0};  // normalised before use
    for (const glm::vec3& n : areaWeightedVertexNormals(mesh, sideways)) EXPECT_EQ(n, glm::vec3(0, 1, 0));

    VertexNormalOptions broken;
    broken.fallbackNormal = {kNaN, 0, 0};  // not a direction: (0, 0, 1) instead
    for (const glm::vec3& n : areaWeightedVertexNormals(mesh, broken)) EXPECT_EQ(n, glm::vec3(0, 0, 1));
    VertexNormalOptions zero;
    zero.fallbackNormal = {0, 0, 0};
    for (const glm::vec3& n : areaWeightedVertexNormals(mesh, zero)) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(AreaWeightedNormals, UnusedVertexOfAnOpenMeshTakesTheMeshDirection) {
    Mesh grid = makeGrid(1.0f, 1.0f, 2, 2);
    grid.positions.push_back({7, 7, 7});
    computeVertexNormals(grid);
    EXPECT_EQ(grid.normals.back(), glm::vec3(0, 1, 0));
}

TEST(AreaWeightedNormals, UnusedVertexOfAClosedMeshTakesTheFallback) {
    Mesh sphere = makeIcosphere(1.0f, 2);
    sphere.positions.push_back({7, 7, 7});
    const NormalStats stats = computeVertexNormals(sphere);
    EXPECT_EQ(stats.fallbackVertices, 1u);
    EXPECT_EQ(sphere.normals.back(), glm::vec3(0, 0, 1));
}

TEST(AreaWeightedNormals, OppositeFacesThatCancelLeaveNoDirection) {
    // A two-sided sheet: the same triangle twice, once per winding.
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 1};
    const NormalStats stats = computeVertexNormals(mesh);
    EXPECT_EQ(stats.degenerateTriangles, 0u);
    EXPECT_EQ(stats.fallbackVertices, 3u);
    EXPECT_TRUE(hasUnitNormals(mesh));
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
}

TEST(AreaWeightedNormals, BigTrianglesOutweighSmallOnesByArea) {
    // Same shape as the thesis example with the small triangle shrunk 1000x: the
    // shared normal moves towards the big triangle's normal.
    Mesh mesh = thesisExample();
    mesh.positions[1] /= 1000.0f;
    mesh.positions[2] /= 1000.0f;
    const glm::vec3 shared = areaWeightedVertexNormals(mesh)[0];
    EXPECT_GT(shared.x, 0.9999f);
    EXPECT_GT(shared.z, 0.0f);
}

class ScaledSphere : public ::testing::TestWithParam<float> {};

TEST_P(ScaledSphere, NormalsAreTheSameAtEveryScale) {
    const Mesh reference = makeIcosphere(1.0f, 3);
    const std::vector<glm::vec3> expected = areaWeightedVertexNormals(reference);
    Mesh scaled = reference;
    for (glm::vec3& p : scaled.positions) p *= GetParam();
    const NormalStats stats = computeVertexNormals(scaled);
    EXPECT_EQ(stats.degenerateTriangles, 0u);
    EXPECT_TRUE(hasUnitNormals(scaled));
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_GT(glm::dot(scaled.normals[i], expected[i]), 0.99999f);
}

INSTANTIATE_TEST_SUITE_P(Extremes, ScaledSphere, ::testing::Values(1e-30f, 1e-12f, 1e-6f, 1e6f, 1e12f, 1e30f));

TEST(AreaWeightedNormals, CoordinatesNearFloatMaxDoNotOverflow) {
    Mesh mesh;
    mesh.positions = {{-3e38f, -3e38f, 0}, {3e38f, -3e38f, 0}, {0, 3e38f, 0}};
    mesh.indices = {0, 1, 2};
    computeVertexNormals(mesh);
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(AreaWeightedNormals, DenormalCoordinatesStillGiveTheNormal) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1e-40f, 0, 0}, {0, 0, 1e-40f}};
    mesh.indices = {0, 1, 2};
    computeVertexNormals(mesh);
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, -1, 0));
}

TEST(AreaWeightedNormals, InvalidMeshIsRejectedWithAClearMessage) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 3};
    try {
        areaWeightedVertexNormals(mesh);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("triangle 0 uses vertex 3"), std::string::npos) << e.what();
    }
    mesh.indices = {0, 1};
    EXPECT_THROW(areaWeightedVertexNormals(mesh), std::invalid_argument);
}

TEST(FaceNormals, DegenerateFaceTakesItsCornersDirection) {
    Mesh grid = makeGrid(1.0f, 1.0f, 1, 1);
    grid.indices.insert(grid.indices.end(), {0, 0, 1});  // repeated index
    const std::vector<glm::vec3> perFace = faceNormals(grid);
    ASSERT_EQ(perFace.size(), 3u);
    for (const glm::vec3& n : perFace) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(FaceNormals, FlatShadedCubeSphereHasOneNormalPerFace) {
    const Mesh flat = makeFlatShaded(makeIcosphere(1.0f, 1));
    ASSERT_EQ(flat.positions.size(), 80u * 3u);
    EXPECT_TRUE(hasUnitNormals(flat));
    for (std::size_t t = 0; t < 80; ++t) {
        EXPECT_EQ(flat.normals[3 * t], flat.normals[3 * t + 1]);
        EXPECT_EQ(flat.normals[3 * t], flat.normals[3 * t + 2]);
        EXPECT_GT(glm::dot(flat.normals[3 * t], flat.positions[3 * t]), 0.0f);
    }
}

TEST(SafeNormalize, NeverReturnsNaN) {
    const glm::vec3 fallback(0, 0, 1);
    EXPECT_EQ(safeNormalize({0, 0, 0}, fallback), fallback);
    EXPECT_EQ(safeNormalize({kNaN, 1, 0}, fallback), fallback);
    EXPECT_EQ(safeNormalize({kInf, 0, 0}, fallback), fallback);
    EXPECT_EQ(safeNormalize({1e-45f, 0, 0}, fallback), glm::vec3(1, 0, 0));
    EXPECT_EQ(safeNormalize({3e38f, 0, 0}, fallback), glm::vec3(1, 0, 0));
    const glm::vec3 big = safeNormalize({3e38f, 3e38f, 3e38f}, fallback);
    EXPECT_TRUE(isFinite(big));
    EXPECT_NEAR(glm::length(big), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace prism::geometry
