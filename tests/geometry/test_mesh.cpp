// Tests of the Mesh helpers: counts, bounds, validation and per-face splitting.
#include "prism/geometry/mesh.hpp"
#include "prism/geometry/procedural_meshes.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace prism::geometry {
namespace {

TEST(Mesh, CountsTrianglesAndVertices) {
    const Mesh cube = makeCube();
    EXPECT_EQ(vertexCount(cube), 24u);
    EXPECT_EQ(triangleCount(cube), 12u);
    EXPECT_EQ(triangleCount(Mesh{}), 0u);
}

TEST(Mesh, BoundsSkipNonFinitePositions) {
    Mesh mesh;
    mesh.positions = {{1, 2, 3},
                      {-1, 5, 0},
                      {std::numeric_limits<float>::quiet_NaN(), 0, 0},
                      {std::numeric_limits<float>::infinity(), 0, 0}};
    const Bounds box = computeBounds(mesh);
    EXPECT_EQ(box.min, glm::vec3(-1, 2, 0));
    EXPECT_EQ(box.max, glm::vec3(1, 5, 3));
    EXPECT_EQ(box.center(), glm::vec3(0, 3.5f, 1.5f));
    EXPECT_EQ(box.size(), glm::vec3(2, 3, 3));
    EXPECT_FALSE(box.isEmpty());
}

TEST(Mesh, BoundsOfNothingAreEmpty) {
    const Bounds box = computeBounds(Mesh{});
    EXPECT_TRUE(box.isEmpty());
    EXPECT_EQ(box.size(), glm::vec3(0.0f));
    EXPECT_EQ(computeBounds(makeCube(2.0f)).size(), glm::vec3(2.0f));
}

TEST(Mesh, FindsStructuralProblems) {
    Mesh mesh = makeCube();
    EXPECT_FALSE(findMeshProblem(mesh).has_value());
    mesh.indices.push_back(0);
    EXPECT_NE(findMeshProblem(mesh).value().find("not a multiple of 3"), std::string::npos);
    mesh = makeCube();
    mesh.indices[7] = 24;
    EXPECT_NE(findMeshProblem(mesh).value().find("triangle 2 uses vertex 24"), std::string::npos);
    mesh = makeCube();
    mesh.normals.pop_back();
    EXPECT_NE(findMeshProblem(mesh).value().find("23 normals for 24 positions"), std::string::npos);
    mesh = makeCube();
    mesh.uvs.resize(3);
    EXPECT_NE(findMeshProblem(mesh).value().find("3 uvs"), std::string::npos);
    EXPECT_THROW(requireValidMesh(mesh, "test"), std::invalid_argument);
}

TEST(Mesh, SplitVerticesPerFaceCopiesEveryCorner) {
    const Mesh cube = makeCube();
    const Mesh split = splitVerticesPerFace(cube);
    ASSERT_EQ(split.positions.size(), 36u);
    ASSERT_EQ(split.normals.size(), 36u);
    ASSERT_EQ(split.uvs.size(), 36u);
    for (std::size_t corner = 0; corner < 36; ++corner) {
        EXPECT_EQ(split.indices[corner], corner);
        EXPECT_EQ(split.positions[corner], cube.positions[cube.indices[corner]]);
        EXPECT_EQ(split.normals[corner], cube.normals[cube.indices[corner]]);
        EXPECT_EQ(split.uvs[corner], cube.uvs[cube.indices[corner]]);
    }
}

}  // namespace
}  // namespace prism::geometry
