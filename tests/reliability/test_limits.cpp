// Prism's stated resource limits (docs/reliability.md), one test per limit: each input
// past a limit ends in a clear error that names the limit, never a crash, a hang or an
// attempt to allocate what the input claims; the largest input within a limit passes.
// The preprocessor limits (include depth, #if nesting, expression length, macro
// expansion) belong to the include resolver of issue 17 and are tested with it.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <zlib.h>

#include "contract.hpp"
#include "variants.hpp"
#include "prism/geometry/obj_loader.hpp"
#include "prism/image/png_io.hpp"
#include "prism/io/json_nesting.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/water/height_field.hpp"

namespace {

std::string nested(int depth) {
    return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']');
}

std::string sceneError(const std::string& text) {
    try {
        prism::scene::parseScene(text, "limits.json");
    } catch (const prism::scene::SceneError& e) {
        return e.what();
    }
    return "";
}

std::filesystem::path tempFile(const std::string& name, const std::string& bytes) {
    const auto dir = std::filesystem::temp_directory_path() / ("prism-limits-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// --- JSON nesting depth: 64 levels for scenes and contracts ---

TEST(JsonDepthLimit, SceneWith100000NestedArraysIsAnErrorNamingTheLimit) {
    const std::string e = sceneError("{\"comment\": " + nested(100000) + "}");
    EXPECT_NE(e.find("limits.json:1:"), std::string::npos) << e;
    EXPECT_NE(e.find("nested more than 64 levels deep (the limit)"), std::string::npos) << e;
}

TEST(JsonDepthLimit, SceneAtTheLimitIsRead) {
    EXPECT_EQ(sceneError("{\"comment\": " + nested(63) + "}"), "");  // the object is level 1
    EXPECT_NE(sceneError("{\"comment\": " + nested(64) + "}").find("the limit"), std::string::npos);
}

TEST(JsonDepthLimit, BracketsInsideStringsDoNotCount) {
    EXPECT_EQ(sceneError("{\"comment\": \"" + std::string(1000, '[') + "\\\"" + std::string(1000, '{') + "\"}"), "");
}

TEST(JsonDepthLimit, ContractWith100000NestedArraysIsAnErrorNamingTheLimit) {
    using namespace prism::shaderc;
    MemoryReader files{{"c.json", "{\"attributes\": " + nested(100000) + "}"}};
    const auto r = loadContracts({"c.json"}, files);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].file, "c.json");
    EXPECT_EQ(r.diagnostics[0].line, 1);
    EXPECT_NE(r.diagnostics[0].message.find("nested more than 64 levels deep (the limit)"), std::string::npos)
        << r.diagnostics[0].message;
    MemoryReader within{{"c.json", "{\"attributes\": [], \"uniforms\": [], \"x\": " + nested(62) + "}"}};
    EXPECT_TRUE(loadContracts({"c.json"}, within).diagnostics.empty());
}

// The one line:column of a JSON error (prism/io/json_nesting.hpp): 1-based line and column of
// the byte at a 0-based offset, for scenes and contracts alike.
TEST(JsonErrorPosition, LineAndColumnCountFromOneAtAZeroBasedOffset) {
    const std::string text = "ab\ncd";
    const auto at = [&](std::size_t offset) {
        const auto [line, column] = prism::io::lineColumnAt(text, offset);
        return std::to_string(line) + ":" + std::to_string(column);
    };
    EXPECT_EQ(at(0), "1:1");
    EXPECT_EQ(at(1), "1:2");
    EXPECT_EQ(at(2), "1:3");  // the newline ends line 1
    EXPECT_EQ(at(3), "2:1");
    EXPECT_EQ(at(4), "2:2");
    EXPECT_EQ(at(99), "2:3");  // past the end: after the last byte
}

TEST(JsonErrorPosition, SceneAndContractNameTheSameLineAndColumn) {
    using namespace prism::shaderc;
    const std::string tooDeep = "{\n  \"x\": " + nested(100) + "}";  // level 65 opens at 2:71
    const std::string malformed = "{\n  \"x\": ]\n}";                // the ']' at 2:8
    for (const auto& [text, position] : {std::pair{tooDeep, std::string(":2:71:")}, {malformed, ":2:8:"}}) {
        EXPECT_EQ(sceneError(text).rfind("limits.json" + position, 0), 0u) << sceneError(text);
        MemoryReader files{{"c.json", text}};
        const auto r = loadContracts({"c.json"}, files);
        ASSERT_EQ(r.diagnostics.size(), 1u);
        EXPECT_EQ(":" + std::to_string(r.diagnostics[0].line) + ":" + std::to_string(r.diagnostics[0].column) + ":",
                  position)
            << r.diagnostics[0].message;
    }
}

// --- Variant combinations per shader: 4096 ---

std::vector<prism::shaderc::Axis> booleanAxes(int count) {
    std::vector<prism::shaderc::Axis> axes;
    for (int i = 0; i < count; ++i) axes.push_back({"AXIS" + std::to_string(i), {"0", "1"}});
    return axes;
}

TEST(VariantLimit, TwelveBooleanAxesGive4096Choices) {
    const auto r = prism::shaderc::variantChoices("s", booleanAxes(12), {});
    EXPECT_TRUE(r.diagnostics.empty());
    EXPECT_EQ(r.choices.size(), 4096u);
}

TEST(VariantLimit, SixtyFourBooleanAxesAreAnErrorNamingTheLimitAtOnce) {
    for (int count : {13, 64}) {
        const auto r = prism::shaderc::variantChoices("s", booleanAxes(count), {});
        ASSERT_EQ(r.diagnostics.size(), 1u) << count;
        EXPECT_TRUE(r.choices.empty());
        EXPECT_EQ(r.diagnostics[0].message,
                  "shader 's' declares more than 4096 variant combinations (the limit); declare fewer axes or values");
    }
}

// --- Scene budgets: image size, rain particles, water grid ---

TEST(SceneBudgetLimits, ImageSide16384) {
    EXPECT_EQ(sceneError(R"({"image": {"width": 16384, "height": 16384}})"), "");
    EXPECT_NE(
        sceneError(R"({"image": {"width": 16385}})").find("/image/width: expected a whole number from 1 to 16384"),
        std::string::npos);
}

TEST(SceneBudgetLimits, RainParticleBudget2To24) {
    EXPECT_EQ(sceneError(R"({"rain": {"budget": 16777216}})"), "");
    const std::string e = sceneError(R"({"rain": {"budget": 16777217}})");
    EXPECT_NE(e.find("/rain/budget: expected a whole number from 0 to 16777216"), std::string::npos) << e;
}

TEST(SceneBudgetLimits, WaterGrid2048) {
    EXPECT_EQ(sceneError(R"({"water": {"grid": 2048}})"), "");
    const std::string e = sceneError(R"({"water": {"grid": 2049}})");
    EXPECT_NE(e.find("/water/grid: expected a whole number from 1 to 2048"), std::string::npos) << e;
}

TEST(SceneBudgetLimits, HugeAndOverflowingNumbersAreSceneErrors) {
    EXPECT_NE(sceneError(R"({"rain": {"budget": 18446744073709551615}})").find("/rain/budget"), std::string::npos);
    EXPECT_NE(sceneError(R"({"rain": {"budget": -9223372036854775808}})").find("/rain/budget"), std::string::npos);
    EXPECT_NE(sceneError(R"({"fog": {"density": 1e400}})").find("limits.json"), std::string::npos);
}

// --- OBJ: indices past 2^31, corners per face ---

std::string objError(const std::string& text) {
    try {
        prism::geometry::loadObj(tempFile("limits.obj", text));
    } catch (const prism::geometry::ObjLoadError& e) {
        return e.what();
    }
    return "";
}

TEST(ObjLimits, IndexOf2To31IsOutOfRange) {
    const std::string e = objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n");
    EXPECT_NE(e.find(":4: error: position index 2147483648 is out of range: the file defines 3 positions"),
              std::string::npos)
        << e;
}

TEST(ObjLimits, MostNegativeRelativeIndexIsAnError) {
    const std::string e = objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9223372036854775808\n");
    EXPECT_NE(e.find("relative position index -9223372036854775808 reaches before the first position"),
              std::string::npos)
        << e;
}

std::string polygon(int corners) {
    std::string text;
    for (int i = 0; i < corners; ++i) {
        const double a = 6.283185307179586 * i / corners;
        text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    text += "f";
    for (int i = 1; i <= corners; ++i) text += " " + std::to_string(i);
    return text + "\n";
}

TEST(ObjLimits, FaceOf4096CornersLoadsAnd4097IsAnErrorNamingTheLimit) {
    EXPECT_EQ(objError(polygon(4096)), "");
    const std::string e = objError(polygon(4097));
    EXPECT_NE(e.find("`f` has 4097 corners, more than the limit of 4096 per face"), std::string::npos) << e;
}

// --- Image dimensions: 16384 a side, 2^26 pixels ---

std::string chunk(const std::string& type, const std::string& data) {
    auto be32 = [](std::uint32_t v) {
        return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                           static_cast<char>(v)};
    };
    const std::string body = type + data;
    const auto crc = crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
    return be32(static_cast<std::uint32_t>(data.size())) + body + be32(static_cast<std::uint32_t>(crc));
}

// A valid PNG header claiming width x height 8-bit grey pixels, with an empty IDAT
// (readers stop at the first IDAT before they allocate the pixels).
std::string pngHeader(std::uint32_t width, std::uint32_t height) {
    std::string ihdr;
    for (std::uint32_t v : {width, height})
        for (int s = 24; s >= 0; s -= 8) ihdr += static_cast<char>(v >> s);
    ihdr += std::string{8, 0, 0, 0, 0};  // depth 8, grey, deflate, adaptive filter, no interlace
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) +
           chunk("IDAT", std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8)) + chunk("IEND", "");
}

TEST(ImageLimits, HeightMapHeaderOf65536x65536IsRefusedBeforeAllocating) {
    const auto path = tempFile("huge.png", pngHeader(65536, 65536));
    try {
        prism::water::loadHeightMap(path);
        FAIL() << "a 65536x65536 map loaded";
    } catch (const prism::water::HeightMapError& e) {
        EXPECT_NE(std::string(e.what()).find("65536x65536 pixels is past the limit for height and permeability maps "
                                             "(16384 a side, 67108864 in all)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(ImageLimits, HeightMapCellLimitHoldsBelowTheSideLimit) {
    const auto path = tempFile("wide.png", pngHeader(8193, 8193));  // each side fine, 8193^2 > 2^26
    EXPECT_THROW(prism::water::loadHeightMap(path), prism::water::HeightMapError);
}

TEST(ImageLimits, ReadPngHeaderOf65536x65536IsRefusedBeforeAllocating) {
    const auto path = tempFile("huge_rgba.png", pngHeader(65536, 65536));
    try {
        prism::image::readPng(path);
        FAIL() << "a 65536x65536 image loaded";
    } catch (const prism::image::PngError& e) {
        EXPECT_NE(std::string(e.what()).find("65536x65536 pixels is past the limit (16384 a side"), std::string::npos)
            << e.what();
    }
}

TEST(ImageLimits, MapAtTheSideLimitLoads) {
    prism::water::GreyImage row{16384, 1, 8, std::vector<std::uint16_t>(16384, 7)};
    const auto path = tempFile("row.png", "");
    prism::water::writeGreyPng(path, row);
    EXPECT_EQ(prism::water::loadHeightMap(path).width, 16384);
    EXPECT_EQ(prism::image::readPng(path).width, 16384);
}

}  // namespace
