// Tests of OBJ import: good files (triangles, quads, normals, uvs, relative indices,
// CRLF), welding after import, and errors naming file and line.
#include "prism/geometry/obj_loader.hpp"

#include "mesh_checks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <unistd.h>

namespace prism::geometry {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class ObjLoader : public ::testing::Test {
  protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        directory_ = fs::temp_directory_path() /
                     ("prism_obj_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(directory_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(directory_, ignored);
    }

    fs::path write(const std::string& name, const std::string& text) {
        const fs::path file = directory_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    // The message of the ObjLoadError thrown by loading `file`.
    static std::string errorOf(const fs::path& file, std::size_t* line = nullptr) {
        try {
            loadObj(file);
        } catch (const ObjLoadError& e) {
            if (line) *line = e.line();
            return e.what();
        }
        return "no error";
    }

    fs::path directory_;
};

const char* const kCubeQuads = R"(# a unit cube, one quad per face, no normals or uvs
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
)";

TEST_F(ObjLoader, QuadCubeIsTriangulatedAndSplitPerFace) {
    const Mesh mesh = loadObj(write("cube.obj", kCubeQuads));
    EXPECT_EQ(triangleCount(mesh), 12u);
    EXPECT_EQ(mesh.positions.size(), 36u);
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_TRUE(testing::hasUnitNormals(mesh));
    EXPECT_GT(testing::signedVolume(mesh), 7.99);            // CCW from outside, volume 8
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)  // flat: normal is the face axis
        EXPECT_FLOAT_EQ(glm::dot(mesh.normals[i], mesh.positions[i]), 1.0f);
}

TEST_F(ObjLoader, WeldingAfterImportGives8Or24Vertices) {
    const fs::path file = write("cube.obj", kCubeQuads);
    ObjLoadOptions smooth;
    smooth.weld = true;
    const Mesh welded = loadObj(file, smooth);
    EXPECT_EQ(welded.positions.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_GT(glm::dot(welded.normals[i], welded.positions[i]), 0.5f);
    ObjLoadOptions sharp = smooth;
    sharp.creaseAngleDegrees = 30.0f;
    EXPECT_EQ(loadObj(file, sharp).positions.size(), 24u);
}

TEST_F(ObjLoader, KeepsFileNormalsAndUvsWithRelativeIndicesAndCrlf) {
    const fs::path file = write("tri.obj",
                                "o triangle\r\n"
                                "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\n"
                                "vt 0 0\r\nvt 1 0\r\nvt 0 1\r\n"
                                "vn 0 0 2\r\n"  // not unit: normalised on load
                                "f -3/-3/-1 -2/-2/-1 -1/-1/-1\r\n");
    const Mesh mesh = loadObj(file);
    ASSERT_EQ(mesh.positions.size(), 3u);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.uvs[1], glm::vec2(1, 0));
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST_F(ObjLoader, ZeroFileNormalFallsBackToTheFaceNormal) {
    const fs::path file = write("zero_normal.obj", "v 0 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    for (const glm::vec3& n : loadObj(file).normals) EXPECT_EQ(n, glm::vec3(1, 0, 0));
    ObjLoadOptions computed;
    computed.useFileNormals = false;
    for (const glm::vec3& n : loadObj(file, computed).normals) EXPECT_EQ(n, glm::vec3(1, 0, 0));
}

TEST_F(ObjLoader, MissingFileNamesThePathAndWhatToDo) {
    const fs::path missing = directory_ / "no_such_mesh.obj";
    std::size_t line = 99;
    const std::string message = errorOf(missing, &line);
    EXPECT_EQ(message.rfind(missing.string() + ": error: cannot open the file", 0), 0u) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    EXPECT_NE(message.find("check that the path is right"), std::string::npos) << message;
    EXPECT_EQ(line, 0u);
}

TEST_F(ObjLoader, DirectoryIsNotAFile) {
    EXPECT_NE(errorOf(directory_).find("is a directory"), std::string::npos);
}

struct MalformedCase {
    const char* name;
    const char* text;
    std::size_t line;
    const char* expected;  // part of the message
};

void PrintTo(const MalformedCase& c, std::ostream* out) {
    *out << c.name;
}

class MalformedObj : public ObjLoader, public ::testing::WithParamInterface<MalformedCase> {};

TEST_P(MalformedObj, ErrorNamesFileAndLine) {
    const MalformedCase& c = GetParam();
    const fs::path file = write(std::string(c.name) + ".obj", c.text);
    std::size_t line = 0;
    const std::string message = errorOf(file, &line);
    EXPECT_EQ(line, c.line) << message;
    const std::string location = file.string() + ":" + std::to_string(c.line) + ": error: ";
    EXPECT_EQ(message.rfind(location, 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MalformedObj,
    ::testing::Values(
        MalformedCase{"NonNumericCoordinate", "v 0 0 0\n# comment\nv 1.0 abc 2.0\nv 0 1 0\nf 1 2 3\n", 3,
                      "`v` needs 3 numeric coordinates (x y z, x y z w or x y z r g b), got 'abc'"},
        MalformedCase{"TooFewCoordinates", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1, "got 2 numbers"},
        MalformedCase{"NaNCoordinate", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
        MalformedCase{"IndexOutOfRange", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 3\nf 1 2 9\n", 6,
                      "position index 9 is out of range: the file defines 3 positions"},
        MalformedCase{"ZeroIndex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "index 0 is invalid"},
        MalformedCase{"RelativeIndexTooFarBack", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3,
                      "relative position index -3 reaches before the first position (2 defined so far)"},
        MalformedCase{"NormalIndexOutOfRange", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n", 5,
                      "normal index 2 is out of range"},
        MalformedCase{"TexcoordIndexNotInteger", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/x 2/1 3/1\n", 5,
                      "texture coordinate index 'x' is not an integer"},
        MalformedCase{"TwoCornerFace", "v 0 0 0\nv 1 0 0\nf 1 2\n", 3, "`f` needs at least 3 corners, got 2"},
        MalformedCase{"BadNormal", "v 0 0 0\nvn 0 0\n", 2, "`vn` needs 3 numeric components"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST_F(ObjLoader, FileWithoutFacesIsAnError) {
    const std::string message = errorOf(write("points.obj", "v 0 0 0\nv 1 0 0\n"));
    EXPECT_NE(message.find("contains no faces"), std::string::npos) << message;
}

}  // namespace
}  // namespace prism::geometry
