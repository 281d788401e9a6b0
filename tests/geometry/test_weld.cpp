// Tests of welding: split cubes and spheres, crease angles, uv seams, -0.0, NaN, and
// agreement of the O(n) hash weld with the O(n^2) search of the FUDGE shader thesis (§6.3).
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/geometry/weld.hpp"

#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace prism::geometry {
namespace {

using testing::hasUnitNormals;

Mesh withoutAttributes(Mesh mesh) {
    mesh.normals.clear();
    mesh.uvs.clear();
    return mesh;
}

WeldOptions crease(float degrees) {
    WeldOptions options;
    options.creaseAngleDegrees = degrees;
    return options;
}

// What an OBJ importer gives for a cube without texture coordinates: 36 vertices.
Mesh importedCube() {
    return withoutAttributes(splitVerticesPerFace(makeCube()));
}

TEST(Weld, SplitCubeWithoutCreaseBecomes8SmoothCorners) {
    const WeldResult welded = weldVertices(importedCube());
    EXPECT_EQ(welded.mesh.positions.size(), 8u);
    EXPECT_EQ(triangleCount(welded.mesh), 12u);
    EXPECT_TRUE(hasUnitNormals(welded.mesh));
    for (std::size_t i = 0; i < 8; ++i) {
        const glm::vec3 corner = welded.mesh.positions[i];
        const glm::vec3 n = welded.mesh.normals[i];
        // Outward, strictly between the three faces it touches.
        EXPECT_GT(n.x * corner.x, 0.0f);
        EXPECT_GT(n.y * corner.y, 0.0f);
        EXPECT_GT(n.z * corner.z, 0.0f);
    }
}

TEST(Weld, SplitCubeWith30DegreeCreaseKeeps24FlatVertices) {
    const Mesh cube = makeCube();
    const WeldResult welded = weldVertices(importedCube(), crease(30.0f));
    ASSERT_EQ(welded.mesh.positions.size(), 24u);
    for (std::size_t t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(welded.mesh.normals[welded.mesh.indices[3 * t + k]], cube.normals[cube.indices[3 * t]]);
}

TEST(Weld, CreaseAngleDecidesAtNinetyDegrees) {
    EXPECT_EQ(weldVertices(importedCube(), crease(89.0f)).mesh.positions.size(), 24u);
    EXPECT_EQ(weldVertices(importedCube(), crease(90.0f)).mesh.positions.size(), 8u);
    EXPECT_EQ(weldVertices(importedCube(), crease(180.0f)).mesh.positions.size(), 8u);
}

TEST(Weld, UvSeamsAreKeptUnlessAskedOtherwise) {
    const Mesh texturedSplitCube = splitVerticesPerFace(makeCube());
    EXPECT_EQ(weldVertices(texturedSplitCube, crease(30.0f)).mesh.positions.size(), 24u);
    WeldOptions ignoreUvs;
    ignoreUvs.keepUvSeams = false;
    const WeldResult welded = weldVertices(texturedSplitCube, ignoreUvs);
    EXPECT_EQ(welded.mesh.positions.size(), 8u);
    EXPECT_EQ(welded.mesh.uvs.size(), 8u);  // each keeps its first vertex's uv
}

TEST(Weld, SplitIcosphereWeldsBackToTheOriginal) {
    const Mesh original = makeIcosphere(1.0f, 3);
    const Mesh split = splitVerticesPerFace(withoutAttributes(original));
    ASSERT_EQ(split.positions.size(), 3u * 1280u);
    for (const WeldOptions& options : {WeldOptions{}, crease(30.0f)}) {
        const WeldResult welded = weldVertices(split, options);
        EXPECT_EQ(welded.mesh.positions.size(), original.positions.size());
        const std::vector<glm::vec3> expected = areaWeightedVertexNormals(original);
        for (std::size_t corner = 0; corner < split.positions.size(); ++corner) {
            const std::uint32_t welded_vertex = welded.newIndexOfOldVertex[corner];
            const std::uint32_t original_vertex = original.indices[corner];
            EXPECT_EQ(welded.mesh.positions[welded_vertex], original.positions[original_vertex]);
            EXPECT_GT(glm::dot(welded.mesh.normals[welded_vertex], expected[original_vertex]), 0.999999f);
        }
    }
}

TEST(Weld, SplitUvSphereWeldsBackToTheOriginalCount) {
    const std::uint32_t rings = 12, segments = 24;
    const Mesh original = makeUvSphere(1.0f, rings, segments);
    const Mesh split = splitVerticesPerFace(original);
    // uv seams kept: exactly the original vertices (every one is used).
    EXPECT_EQ(weldVertices(split).mesh.positions.size(), original.positions.size());
    EXPECT_EQ(weldVertices(split, crease(30.0f)).mesh.positions.size(), original.positions.size());
    // By position alone: one vertex per pole and no seam column.
    WeldOptions byPosition;
    byPosition.keepUvSeams = false;
    EXPECT_EQ(weldVertices(split, byPosition).mesh.positions.size(), 2u + (rings - 1) * segments);
}

TEST(Weld, NegativeZeroEqualsZero) {
    Mesh mesh;
    mesh.positions = {{0.0f, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, -0.0f, 0.0f}, {0, 1, 0}, {-1, 0, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 5};
    const WeldResult welded = weldVertices(mesh);
    EXPECT_EQ(welded.mesh.positions.size(), 4u);
    EXPECT_EQ(welded.newIndexOfOldVertex[0], welded.newIndexOfOldVertex[3]);
    EXPECT_EQ(weldQuadraticReference(mesh).newIndexOfOldVertex, welded.newIndexOfOldVertex);
}

TEST(Weld, NonFinitePositionsAreNeverMergedAndGiveNoNaNNormals) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 0, 0}, {nan, 0, 0}, {inf, 0, 0}, {inf, 0, 0}};
    mesh.indices = {0, 1, 2, 3, 4, 0, 5, 6, 1};
    const WeldResult welded = weldVertices(mesh, crease(30.0f));
    EXPECT_EQ(welded.mesh.positions.size(), 7u);
    EXPECT_TRUE(hasUnitNormals(welded.mesh));
    EXPECT_EQ(weldQuadraticReference(mesh, crease(30.0f)).newIndexOfOldVertex, welded.newIndexOfOldVertex);
}

TEST(Weld, DegenerateVerticesJoinTheFirstGroupAtTheirPosition) {
    Mesh mesh = importedCube();
    // A zero-area sliver at a cube corner: its vertices have no direction.
    const glm::vec3 corner = mesh.positions[0];
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {corner, corner, corner});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
    const WeldResult welded = weldVertices(mesh, crease(30.0f));
    EXPECT_EQ(welded.mesh.positions.size(), 24u);
    EXPECT_EQ(welded.newIndexOfOldVertex[first], welded.newIndexOfOldVertex[0]);
}

TEST(Weld, KeepsExistingNormalsWhenNotRecomputing) {
    const Mesh split = splitVerticesPerFace(makeCube());
    WeldOptions keep = crease(30.0f);
    keep.recomputeNormals = false;
    const WeldResult welded = weldVertices(split, keep);
    ASSERT_EQ(welded.mesh.normals.size(), 24u);
    for (std::size_t i = 0; i < split.positions.size(); ++i)
        EXPECT_EQ(welded.mesh.normals[welded.newIndexOfOldVertex[i]], split.normals[i]);
}

TEST(Weld, RejectsBadCreaseAnglesAndInvalidMeshes) {
    EXPECT_THROW(weldVertices(importedCube(), crease(-1.0f)), std::invalid_argument);
    EXPECT_THROW(weldVertices(importedCube(), crease(std::numeric_limits<float>::quiet_NaN())), std::invalid_argument);
    Mesh broken = importedCube();
    broken.indices.back() = 99;
    EXPECT_THROW(weldVertices(broken), std::invalid_argument);
    EXPECT_THROW(weldQuadraticReference(broken), std::invalid_argument);
}

TEST(Weld, EmptyMeshWeldsToEmpty) {
    const WeldResult welded = weldVertices(Mesh{});
    EXPECT_TRUE(welded.mesh.positions.empty());
    EXPECT_TRUE(welded.newIndexOfOldVertex.empty());
}

// --- O(n) against O(n^2) -----------------------------------------------------------

void expectSameResult(const Mesh& input, const WeldOptions& options) {
    const WeldResult fast = weldVertices(input, options);
    const WeldResult reference = weldQuadraticReference(input, options);
    EXPECT_EQ(fast.newIndexOfOldVertex, reference.newIndexOfOldVertex);
    EXPECT_EQ(fast.mesh.positions, reference.mesh.positions);
    EXPECT_EQ(fast.mesh.indices, reference.mesh.indices);
    EXPECT_EQ(fast.mesh.normals, reference.mesh.normals);
    EXPECT_EQ(fast.mesh.uvs, reference.mesh.uvs);
}

TEST(WeldCrossCheck, HashWeldAgreesWithQuadraticReference) {
    const Mesh inputs[] = {
        importedCube(),
        splitVerticesPerFace(makeCube()),
        splitVerticesPerFace(makeUvSphere(1.0f, 8, 12)),
        splitVerticesPerFace(withoutAttributes(makeTorus(1.0f, 0.3f, 16, 8))),
        splitVerticesPerFace(makeTrefoilKnot({48, 6, 0.1f, 3, 0.2f, 1})),
        splitVerticesPerFace(makeGrid(1.0f, 1.0f, 5, 5)),
        makeIcosphere(1.0f, 2),  // already welded: nothing to merge
    };
    for (const Mesh& input : inputs) {
        for (const WeldOptions& options : {WeldOptions{}, crease(10.0f), crease(30.0f), crease(60.0f)}) {
            expectSameResult(input, options);
            WeldOptions ignoreUvs = options;
            ignoreUvs.keepUvSeams = false;
            expectSameResult(input, ignoreUvs);
        }
    }
}

TEST(WeldCrossCheck, AgreesOnAPseudoRandomSoupWithManyCollisions) {
    // Positions drawn from a small lattice so that many vertices coincide, in random
    // triangles (some degenerate, some with repeated indices), with -0.0 mixed in.
    std::uint32_t state = 12345u;
    auto next = [&] { return state = state * 1664525u + 1013904223u; };
    Mesh soup;
    for (int i = 0; i < 3000; ++i) {
        glm::vec3 p(float(next() % 5) - 2.0f, float(next() % 5) - 2.0f, float(next() % 3) - 1.0f);
        if (next() % 7 == 0) p.x = -0.0f * p.x;  // -0.0 or 0.0 or +-0
        soup.positions.push_back(p);
    }
    for (int t = 0; t < 1000; ++t)
        for (int k = 0; k < 3; ++k) soup.indices.push_back(next() % 3000);
    for (const WeldOptions& options : {WeldOptions{}, crease(45.0f)}) expectSameResult(soup, options);
    EXPECT_LE(weldVertices(soup).mesh.positions.size(), 75u);
}

}  // namespace
}  // namespace prism::geometry
