// The diffraction material's parameters as a scene gives them (JSON), and what they build: the
// height field and the lookup tables of the one path the material uses. The scene loader passes
// the material's "diffraction" object and its JSON pointer; errors name the pointer.
//
// Usage (snippet: examples/snippets/diffraction_material.cpp):
//
//     #include <nlohmann/json.hpp>
//     #include "prism/diffraction/material.hpp"
//     using namespace prism::diffraction;
//     nlohmann::json j = nlohmann::json::parse(R"({"height_field": {"type": "sinusoid", "period_nm": 2500,
//         "amplitude_nm": 60, "periods": 8}, "path": "b", "table_size": 64, "wavelength_step_nm": 20})");
//     DiffractionMaterial m = parseDiffractionMaterial(j, "/objects/0/material/diffraction", ".");
//     StamBrdf brdf = makeBrdf(m);                           // N from the height range and m.tolerance
//     MaterialTables tables = buildMaterialTables(m, brdf);  // only path b's 2N + 1 layers
//
// Keys (all optional except height_field.type; docs/diffraction.md, "Material parameters"):
//   height_field: {type: sinusoid|blazed, period_nm, amplitude_nm, periods, samples_per_period}
//               | {type: cd, pitch_nm, pit_depth_nm, pit_width_nm, size, pixel_nm, seed}
//               | {type: snake, spacing_nm, height_nm, waviness_nm, size, pixel_nm, seed}
//               | {type: png, file, nm_per_pixel, height_scale_nm}   (file relative to baseDir)
//   path: "a" | "b" | "c" (c)   w_slices: 2..256 (8, path c)
//   wavelength_step_nm: 1|2|5|10|20 (5)   table_size: 8..2048 (512)
//   tolerance: (0, 1) (1e-3) or terms: 0..200   coherence_nm: > 0 (a quarter of the patch)
//   tangent: [x, y, z], object-space direction across the grooves ([1, 0, 0]), or "radial":
//            away from the object's y axis (circular grooves, like a CD's tracks)
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include <nlohmann/json_fwd.hpp>

#include "prism/diffraction/lookup_tables.hpp"

namespace prism::diffraction {

// "<pointer>/<key>: <what is wrong>".
struct MaterialError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

struct PngField {
    std::string file;  // resolved against baseDir
    double nmPerPixel = 0.0;
    double heightScaleNm = 0.0;

    bool operator==(const PngField&) const = default;
};

struct DiffractionMaterial {
    std::string heightFieldType;  // sinusoid, blazed, cd, snake, png
    std::variant<GratingParams, TrackParams, RidgeParams, PngField> heightField;
    char path = 'c';  // 'a', 'b' or 'c' (lookup_tables.hpp)
    int wSlices = 8;  // path c
    int wavelengthStepNm = 5;
    int tableSize = 512;
    double tolerance = 1e-3;
    std::optional<int> terms;
    std::optional<double> coherenceNm;
    std::array<double, 3> tangent{1.0, 0.0, 0.0};
    bool radialTangent = false;  // "tangent": "radial" (u_diffractionRadial)

    bool operator==(const DiffractionMaterial&) const = default;  // equal materials share tables
};

DiffractionMaterial parseDiffractionMaterial(const nlohmann::json& object, const std::string& pointer,
                                             const std::string& baseDir);

HeightField makeHeightField(const DiffractionMaterial& material);
// Throws MaterialError (naming the material's tolerance or terms) when N would exceed 200.
StamBrdf makeBrdf(const DiffractionMaterial& material);

struct MaterialTables {
    std::optional<SpectralTables> spectral;      // path a only
    std::optional<IntegratedTables> integrated;  // path b only
    std::optional<VolumeTables> volume;          // path c only
};
MaterialTables buildMaterialTables(const DiffractionMaterial& material, const StamBrdf& brdf);

}  // namespace prism::diffraction
