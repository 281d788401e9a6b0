// Tests of the procedural meshes: counts, unit outward normals, CCW winding seen
// from outside, closedness, determinism and argument checks.
#include "prism/geometry/normals.hpp"
#include "prism/geometry/procedural_meshes.hpp"
#include "prism/geometry/weld.hpp"

#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <ostream>
#include <vector>

namespace prism::geometry {
namespace {

using testing::hasUnitNormals;
using testing::isClosedAndConsistentlyWound;
using testing::signedVolume;
using testing::windingMatchesNormals;

struct NamedMesh {
    const char* name;
    std::function<Mesh()> make;
    bool closed;
    bool sharpEdges = false;
};

const NamedMesh kAllMeshes[] = {
    {"Cube", [] { return makeCube(); }, true, true},
    {"SmallCube", [] { return makeCube(1e-6f); }, true, true},
    {"UvSphere", [] { return makeUvSphere(1.0f, 16, 32); }, true},
    {"CoarseUvSphere", [] { return makeUvSphere(2.0f, 2, 3); }, true},
    {"Icosphere0", [] { return makeIcosphere(1.0f, 0); }, true},
    {"Icosphere4", [] { return makeIcosphere(1e6f, 4); }, true},
    {"Torus", [] { return makeTorus(); }, true},
    {"ThinTorus", [] { return makeTorus(1.0f, 0.01f, 64, 3); }, true},
    {"Grid", [] { return makeGrid(); }, false},
    {"TrefoilKnot", [] { return makeTrefoilKnot(); }, true},
    {"SmoothKnot",
     [] {
         return makeTrefoilKnot({64, 8, 0.15f, 0, 0.0f, 0});
     },
     true},
};

void PrintTo(const NamedMesh& mesh, std::ostream* out) {
    *out << mesh.name;
}

std::vector<NamedMesh> closedMeshes() {
    std::vector<NamedMesh> closed;
    for (const NamedMesh& mesh : kAllMeshes)
        if (mesh.closed) closed.push_back(mesh);
    return closed;
}

class EveryMesh : public ::testing::TestWithParam<NamedMesh> {};
class ClosedMesh : public ::testing::TestWithParam<NamedMesh> {};

TEST_P(EveryMesh, IsValidWithFiniteUnitNormals) {
    const Mesh mesh = GetParam().make();
    EXPECT_FALSE(findMeshProblem(mesh).has_value());
    EXPECT_TRUE(hasUnitNormals(mesh));
    for (const glm::vec3& p : mesh.positions) EXPECT_TRUE(testing::isFinite(p));
}

TEST_P(EveryMesh, WindsCounterClockwiseAroundItsNormals) {
    const Mesh mesh = GetParam().make();
    EXPECT_TRUE(windingMatchesNormals(mesh));
    NormalStats stats;
    areaWeightedVertexNormals(mesh, {}, &stats);
    EXPECT_EQ(stats.degenerateTriangles, 0u);
}

TEST_P(ClosedMesh, EnclosesAPositiveVolumeWithoutHoles) {
    const Mesh mesh = GetParam().make();
    EXPECT_GT(signedVolume(mesh), 0.0);
    EXPECT_TRUE(isClosedAndConsistentlyWound(mesh));
}

TEST_P(EveryMesh, StoredNormalsAgreeWithTheMeshsOwnAreaWeightedNormals) {
    const Mesh mesh = GetParam().make();
    Mesh geometryOnly{mesh.positions, {}, {}, mesh.indices};
    std::vector<glm::vec3> computed;
    if (GetParam().sharpEdges) {
        computed = areaWeightedVertexNormals(geometryOnly);  // faces share no vertex
    } else {
        // Join uv seams and poles first, then compare every vertex.
        const WeldResult joined = weldVertices(geometryOnly);
        for (std::uint32_t group : joined.newIndexOfOldVertex) computed.push_back(joined.mesh.normals[group]);
    }
    for (std::size_t i = 0; i < computed.size(); ++i)
        EXPECT_GT(glm::dot(computed[i], mesh.normals[i]), 0.9f) << "vertex " << i;
}

TEST_P(EveryMesh, IsDeterministic) {
    const Mesh a = GetParam().make(), b = GetParam().make();
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.indices, b.indices);
}

INSTANTIATE_TEST_SUITE_P(Shapes, EveryMesh, ::testing::ValuesIn(kAllMeshes),
                         [](const auto& info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(Shapes, ClosedMesh, ::testing::ValuesIn(closedMeshes()),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Cube, Has24VerticesWithFlatOutwardFaceNormals) {
    const Mesh cube = makeCube(2.0f);
    ASSERT_EQ(cube.positions.size(), 24u);
    ASSERT_EQ(cube.indices.size(), 36u);
    for (std::size_t t = 0; t < 12; ++t) {
        const glm::vec3 n = cube.normals[cube.indices[3 * t]];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = cube.positions[cube.indices[3 * t + k]];
            EXPECT_EQ(cube.normals[cube.indices[3 * t + k]], n);
            EXPECT_FLOAT_EQ(glm::dot(p, n), 1.0f);  // on the face plane at distance 1
        }
        EXPECT_GT(glm::dot(glm::vec3(testing::faceCross(cube, t)), n), 0.0f);
    }
}

TEST(UvSphere, CountsAndOutwardNormals) {
    const std::uint32_t rings = 7, segments = 9;
    const Mesh sphere = makeUvSphere(3.0f, rings, segments);
    EXPECT_EQ(sphere.positions.size(), 2 * segments + (rings - 1) * (segments + 1));
    EXPECT_EQ(triangleCount(sphere), 2u * segments * (rings - 1));
    ASSERT_EQ(sphere.uvs.size(), sphere.positions.size());
    for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(sphere.positions[i]), 3.0f, 1e-5f);
        EXPECT_GT(glm::dot(sphere.normals[i], sphere.positions[i] / 3.0f), 0.99999f);
    }
    // Every vertex is used by some triangle.
    std::vector<bool> used(sphere.positions.size(), false);
    for (std::uint32_t index : sphere.indices) used[index] = true;
    for (bool u : used) EXPECT_TRUE(u);
}

TEST(Icosphere, VertexCountIs10Times4PowLevelPlus2) {
    for (std::uint32_t level = 0; level <= 7; ++level) {
        const Mesh sphere = makeIcosphere(1.0f, level);
        const std::size_t expectedVertices = 10u * (std::size_t(1) << (2 * level)) + 2u;
        EXPECT_EQ(sphere.positions.size(), expectedVertices) << "level " << level;
        EXPECT_EQ(icosphereVertexCount(level), expectedVertices);
        EXPECT_EQ(triangleCount(sphere), 20u * (std::size_t(1) << (2 * level))) << "level " << level;
        if (level <= 4) {
            for (const glm::vec3& p : sphere.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
            for (std::size_t i = 0; i < sphere.positions.size(); ++i)
                EXPECT_GT(glm::dot(sphere.normals[i], sphere.positions[i]), 0.99999f);
        }
    }
}

TEST(Icosphere, LevelAbove7IsRejected) {
    EXPECT_THROW(makeIcosphere(1.0f, 8), std::invalid_argument);
}

TEST(Torus, NormalsPointAwayFromTheTubeCentre) {
    const float major = 2.0f, minor = 0.5f;
    const Mesh torus = makeTorus(major, minor, 24, 12);
    EXPECT_EQ(torus.positions.size(), 25u * 13u);
    EXPECT_EQ(triangleCount(torus), 2u * 24u * 12u);
    for (std::size_t i = 0; i < torus.positions.size(); ++i) {
        const glm::vec3 p = torus.positions[i];
        const glm::vec3 tubeCentre = major * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        EXPECT_GT(glm::dot(torus.normals[i], (p - tubeCentre) / minor), 0.99999f);
    }
}

TEST(Grid, FacesUpWithCcwTriangles) {
    const Mesh grid = makeGrid(4.0f, 2.0f, 3, 5);
    EXPECT_EQ(grid.positions.size(), 4u * 6u);
    EXPECT_EQ(triangleCount(grid), 2u * 3u * 5u);
    for (std::size_t t = 0; t < triangleCount(grid); ++t) EXPECT_GT(testing::faceCross(grid, t).y, 0.0);
    const Bounds box = computeBounds(grid);
    EXPECT_EQ(box.size(), glm::vec3(4.0f, 0.0f, 2.0f));
}

TEST(TrefoilKnot, HasConcaveGroovesAndFitsTheUnitSphere) {
    const Mesh knot = makeTrefoilKnot();
    EXPECT_EQ(knot.positions.size(), 256u * 32u);
    // Convex surface: (n_a - n_b) . (p_a - p_b) >= 0 along every edge. Grooves break it.
    std::size_t concaveEdges = 0;
    for (std::size_t t = 0; t < triangleCount(knot); ++t) {
        const std::uint32_t a = knot.indices[3 * t], b = knot.indices[3 * t + 1];
        concaveEdges += glm::dot(knot.normals[a] - knot.normals[b], knot.positions[a] - knot.positions[b]) < 0.0f;
    }
    EXPECT_GT(concaveEdges, triangleCount(knot) / 10);
    for (const glm::vec3& p : knot.positions) EXPECT_LT(glm::length(p), 1.2f);
}

TEST(TrefoilKnot, TubeDoesNotIntersectItself) {
    // Coarse check: vertices of far-apart path sections stay apart.
    TrefoilKnotShape shape;
    shape.pathSegments = 96;
    shape.tubeSegments = 8;
    shape.tubeRadius = 0.15f;
    shape.ridgeDepth = 0.25f;  // the thickest allowed tube
    const Mesh knot = makeTrefoilKnot(shape);
    float closest = std::numeric_limits<float>::max();
    for (std::uint32_t i = 0; i < 96; ++i)
        for (std::uint32_t j = i + 24; j + 24 <= i + 96; ++j)
            for (std::uint32_t a = 0; a < 8; ++a)
                for (std::uint32_t b = 0; b < 8; ++b)
                    closest =
                        std::min(closest, glm::length(knot.positions[i * 8 + a] - knot.positions[(j % 96) * 8 + b]));
    EXPECT_GT(closest, 0.0f);
    EXPECT_GT(signedVolume(knot), 0.0);
}

TEST(ProceduralMeshes, RejectBadArgumentsWithTheirNames) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto messageOf = [](const std::function<void()>& make) {
        try {
            make();
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_NE(messageOf([] { makeCube(0.0f); }).find("makeCube: edgeLength"), std::string::npos);
    EXPECT_NE(messageOf([&] { makeCube(nan); }).find("edgeLength"), std::string::npos);
    EXPECT_NE(messageOf([] { makeUvSphere(1.0f, 1, 8); }).find("rings"), std::string::npos);
    EXPECT_NE(messageOf([] { makeUvSphere(1.0f, 4, 2); }).find("segments"), std::string::npos);
    EXPECT_NE(messageOf([] { makeTorus(1.0f, 1.0f); }).find("minorRadius"), std::string::npos);
    EXPECT_NE(messageOf([] { makeGrid(1.0f, -1.0f); }).find("depth"), std::string::npos);
    EXPECT_NE(messageOf([] { makeGrid(1.0f, 1.0f, 0, 1); }).find("columns"), std::string::npos);
    EXPECT_NE(messageOf([] { makeTrefoilKnot({256, 32, 0.5f}); }).find("tubeRadius"), std::string::npos);
}

}  // namespace
}  // namespace prism::geometry
