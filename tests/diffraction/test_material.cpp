// The diffraction material's JSON parameters: defaults, every height-field type, only the used
// path's tables, and errors that name the JSON pointer of the bad value.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "prism/diffraction/material.hpp"

using namespace prism::diffraction;
using nlohmann::json;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseDiffractionMaterial(json::parse(text), "/objects/0/material/diffraction", "/scenes");
    } catch (const MaterialError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(DiffractionMaterial, DefaultsAndPathA) {
    const DiffractionMaterial m = parseDiffractionMaterial(
        json::parse(R"({"height_field": {"type": "cd", "size": 64}, "path": "a", "terms": 4})"), "", ".");
    EXPECT_EQ(m.path, 'a');
    EXPECT_EQ(m.wavelengthStepNm, 5);
    EXPECT_EQ(m.tableSize, 512);
    EXPECT_EQ(m.terms, 4);
    EXPECT_EQ(makeHeightField(m).width, 64);
    const DiffractionMaterial snake = parseDiffractionMaterial(
        json::parse(R"({"height_field": {"type": "snake", "size": 32}, "path": "a", "terms": 2, "table_size": 16})"),
        "", ".");
    const MaterialTables tables = buildMaterialTables(snake, makeBrdf(snake));
    EXPECT_TRUE(tables.spectral.has_value());
    EXPECT_FALSE(tables.integrated.has_value());
    EXPECT_FALSE(tables.volume.has_value());
}

TEST(DiffractionMaterial, DefaultPathIsTheVolume) {
    const DiffractionMaterial m = parseDiffractionMaterial(
        json::parse(R"({"height_field": {"type": "sinusoid", "amplitude_nm": 60, "periods": 4},)"
                    R"( "table_size": 16, "w_slices": 4})"),
        "", ".");
    EXPECT_EQ(m.path, 'c');
    const MaterialTables tables = buildMaterialTables(m, makeBrdf(m));
    ASSERT_TRUE(tables.volume.has_value());
    EXPECT_EQ(tables.volume->slices, 4);
    EXPECT_FALSE(tables.spectral.has_value());
    EXPECT_FALSE(tables.integrated.has_value());
}

TEST(DiffractionMaterial, PngPathIsRelativeToTheScene) {
    const DiffractionMaterial m = parseDiffractionMaterial(
        json::parse(
            R"({"height_field": {"type": "png", "file": "scan.png", "nm_per_pixel": 100, "height_scale_nm": 150}})"),
        "", "/scenes");
    EXPECT_EQ(std::get<PngField>(m.heightField).file, "/scenes/scan.png");
    EXPECT_THROW(makeHeightField(m), std::runtime_error);  // no such file: "…/scan.png: error: cannot open"
}

TEST(DiffractionMaterial, ErrorsNameTheJsonPointer) {
    const std::string p = "/objects/0/material/diffraction";
    EXPECT_EQ(errorOf(R"({})"), p + "/height_field: required");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "plasma"}})"),
              p + "/height_field/type: unknown height field \"plasma\" (sinusoid, blazed, cd, snake or png)");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid", "period_nm": -5}})"),
              p + "/height_field/period_nm: expected a number in (0, 1e+09]");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid"}, "wavelength_step_nm": 3})"),
              p + "/wavelength_step_nm: expected 1, 2, 5, 10 or 20");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid"}, "path": "d"})"),
              p + "/path: expected \"a\" (per wavelength), \"b\" (pre-integrated tables) or \"c\" (w volume)");
    EXPECT_NE(errorOf(R"({"height_field": {"type": "sinusoid"}, "colour": 1})").find(p + "/colour: unknown key"),
              std::string::npos);
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "png", "file": "a.png", "nm_per_pixel": 10}})"),
              p + "/height_field/height_scale_nm: required for a PNG height field");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid"}, "terms": 3, "tolerance": 0.1})"),
              p + "/terms: give either tolerance or terms, not both");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid"}, "tangent": [0, 0, 0]})"),
              p + "/tangent: expected a finite non-zero direction");
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "sinusoid"}, "table_size": 4096})"),
              p + "/table_size: expected an integer in [8, 2048]");
}

TEST(DiffractionMaterial, HugeHeightsAreAClearError) {
    const DiffractionMaterial m = parseDiffractionMaterial(
        json::parse(R"({"height_field": {"type": "sinusoid", "amplitude_nm": 20000, "periods": 4}})"), "", ".");
    try {
        makeBrdf(m);
        FAIL();
    } catch (const MaterialError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("tolerance: ", 0), 0u) << e.what();
    }
}

TEST(DiffractionMaterial, RadialTangentForCircularGrooves) {
    const DiffractionMaterial radial =
        parseDiffractionMaterial(json::parse(R"({"height_field": {"type": "cd"}, "tangent": "radial"})"), "/m", ".");
    EXPECT_TRUE(radial.radialTangent);
    const DiffractionMaterial fixed =
        parseDiffractionMaterial(json::parse(R"({"height_field": {"type": "cd"}, "tangent": [0, 0, 2]})"), "/m", ".");
    EXPECT_FALSE(fixed.radialTangent);
    EXPECT_EQ(errorOf(R"({"height_field": {"type": "cd"}, "tangent": "spiral"})"),
              "/objects/0/material/diffraction/tangent: expected [x, y, z] or \"radial\"");
}
