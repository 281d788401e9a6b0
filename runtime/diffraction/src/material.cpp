// Parsing the diffraction material's JSON parameters and building what they ask for (see material.hpp).
#include "prism/diffraction/material.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <set>

#include "prism/diffraction/taylor_bound.hpp"

namespace prism::diffraction {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& pointer, const std::string& message) {
    throw MaterialError(pointer + ": " + message);
}

void rejectUnknownKeys(const json& object, const std::string& pointer, const std::set<std::string>& known) {
    if (!object.is_object()) fail(pointer, "expected an object");
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!known.count(it.key())) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            fail(pointer + "/" + it.key(), "unknown key (expected one of: " + list + ")");
        }
    }
}

double number(const json& object, const std::string& pointer, const std::string& key, double fallback, double low,
              double high, bool lowInclusive = true) {
    if (!object.contains(key)) return fallback;
    const json& v = object.at(key);
    if (!v.is_number()) fail(pointer + "/" + key, "expected a number");
    const double x = v.get<double>();
    const bool aboveLow = lowInclusive ? x >= low : x > low;
    if (!std::isfinite(x) || !aboveLow || x > high) {
        char range[96];
        std::snprintf(range, sizeof range, "expected a number in %s%g, %g]", lowInclusive ? "[" : "(", low, high);
        fail(pointer + "/" + key, range);
    }
    return x;
}

int integer(const json& object, const std::string& pointer, const std::string& key, int fallback, int low, int high) {
    if (!object.contains(key)) return fallback;
    const json& v = object.at(key);
    if (!v.is_number_integer()) fail(pointer + "/" + key, "expected an integer");
    const long long x = v.get<long long>();
    if (x < low || x > high)
        fail(pointer + "/" + key, "expected an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return static_cast<int>(x);
}

void parseHeightField(const json& hf, const std::string& p, const std::string& baseDir, DiffractionMaterial& m) {
    if (!hf.is_object()) fail(p, "expected an object with a \"type\"");
    if (!hf.contains("type") || !hf.at("type").is_string()) {
        fail(p + "/type", "expected one of \"sinusoid\", \"blazed\", \"cd\", \"snake\", \"png\"");
    }
    m.heightFieldType = hf.at("type").get<std::string>();
    const double big = 1e9;
    if (m.heightFieldType == "sinusoid" || m.heightFieldType == "blazed") {
        rejectUnknownKeys(hf, p, {"type", "period_nm", "amplitude_nm", "periods", "samples_per_period"});
        GratingParams g;
        g.periodNm = number(hf, p, "period_nm", g.periodNm, 0.0, big, false);
        g.amplitudeNm = number(hf, p, "amplitude_nm", g.amplitudeNm, 0.0, big);
        g.periods = integer(hf, p, "periods", g.periods, 1, 4096);
        g.samplesPerPeriod = integer(hf, p, "samples_per_period", g.samplesPerPeriod, 4, 1024);
        m.heightField = g;
    } else if (m.heightFieldType == "cd") {
        rejectUnknownKeys(hf, p, {"type", "pitch_nm", "pit_depth_nm", "pit_width_nm", "size", "pixel_nm", "seed"});
        TrackParams t;
        t.pitchNm = number(hf, p, "pitch_nm", t.pitchNm, 0.0, big, false);
        t.pitDepthNm = number(hf, p, "pit_depth_nm", t.pitDepthNm, 0.0, big);
        t.pitWidthNm = number(hf, p, "pit_width_nm", t.pitWidthNm, 0.0, t.pitchNm, false);
        t.size = integer(hf, p, "size", t.size, 8, 4096);
        t.pixelNm = number(hf, p, "pixel_nm", t.pixelNm, 0.0, big, false);
        t.seed = static_cast<std::uint32_t>(integer(hf, p, "seed", 1, 0, 2147483647));
        m.heightField = t;
    } else if (m.heightFieldType == "snake") {
        rejectUnknownKeys(hf, p, {"type", "spacing_nm", "height_nm", "waviness_nm", "size", "pixel_nm", "seed"});
        RidgeParams r;
        r.spacingNm = number(hf, p, "spacing_nm", r.spacingNm, 0.0, big, false);
        r.heightNm = number(hf, p, "height_nm", r.heightNm, 0.0, big);
        r.wavinessNm = number(hf, p, "waviness_nm", r.wavinessNm, 0.0, big);
        r.size = integer(hf, p, "size", r.size, 8, 4096);
        r.pixelNm = number(hf, p, "pixel_nm", r.pixelNm, 0.0, big, false);
        r.seed = static_cast<std::uint32_t>(integer(hf, p, "seed", 1, 0, 2147483647));
        m.heightField = r;
    } else if (m.heightFieldType == "png") {
        rejectUnknownKeys(hf, p, {"type", "file", "nm_per_pixel", "height_scale_nm"});
        if (!hf.contains("file") || !hf.at("file").is_string()) fail(p + "/file", "expected the PNG's path (a string)");
        if (!hf.contains("nm_per_pixel")) fail(p + "/nm_per_pixel", "required for a PNG height field");
        if (!hf.contains("height_scale_nm")) fail(p + "/height_scale_nm", "required for a PNG height field");
        PngField png;
        const std::filesystem::path file = hf.at("file").get<std::string>();
        png.file = file.is_absolute() ? file.string() : (std::filesystem::path(baseDir) / file).string();
        png.nmPerPixel = number(hf, p, "nm_per_pixel", 0.0, 0.0, big, false);
        png.heightScaleNm = number(hf, p, "height_scale_nm", 0.0, 0.0, big);
        m.heightField = png;
    } else {
        fail(p + "/type", "unknown height field \"" + m.heightFieldType + "\" (sinusoid, blazed, cd, snake or png)");
    }
}

}  // namespace

DiffractionMaterial parseDiffractionMaterial(const json& j, const std::string& p, const std::string& baseDir) {
    rejectUnknownKeys(j, p,
                      {"height_field", "path", "w_slices", "wavelength_step_nm", "table_size", "tolerance", "terms",
                       "coherence_nm", "tangent"});
    DiffractionMaterial m;
    if (!j.contains("height_field")) fail(p + "/height_field", "required");
    parseHeightField(j.at("height_field"), p + "/height_field", baseDir, m);
    if (j.contains("path")) {
        const json& path = j.at("path");
        if (!path.is_string() || (path != "a" && path != "b" && path != "c")) {
            fail(p + "/path", "expected \"a\" (per wavelength), \"b\" (pre-integrated tables) or \"c\" (w volume)");
        }
        m.path = path.get<std::string>()[0];
    }
    m.wSlices = integer(j, p, "w_slices", m.wSlices, 2, 256);
    m.wavelengthStepNm = integer(j, p, "wavelength_step_nm", m.wavelengthStepNm, 1, 20);
    if (!isSupportedWavelengthStep(m.wavelengthStepNm)) fail(p + "/wavelength_step_nm", "expected 1, 2, 5, 10 or 20");
    m.tableSize = integer(j, p, "table_size", m.tableSize, 8, 2048);
    if (j.contains("tolerance") && j.contains("terms")) fail(p + "/terms", "give either tolerance or terms, not both");
    m.tolerance = number(j, p, "tolerance", m.tolerance, 0.0, 1.0, false);
    if (m.tolerance >= 1.0) fail(p + "/tolerance", "expected a number in (0, 1)");
    if (j.contains("terms")) m.terms = integer(j, p, "terms", 0, 0, kMaxTaylorTerms);
    if (j.contains("coherence_nm")) m.coherenceNm = number(j, p, "coherence_nm", 0.0, 0.0, 1e9, false);
    if (j.contains("tangent")) {
        const json& t = j.at("tangent");
        if (t.is_string() && t == "radial") {
            m.radialTangent = true;
        } else if (!t.is_array() || t.size() != 3 || !t[0].is_number() || !t[1].is_number() || !t[2].is_number()) {
            fail(p + "/tangent", "expected [x, y, z] or \"radial\"");
        } else {
            m.tangent = {t[0].get<double>(), t[1].get<double>(), t[2].get<double>()};
            const double len = std::hypot(m.tangent[0], m.tangent[1], m.tangent[2]);
            if (!(len > 1e-9) || !std::isfinite(len)) fail(p + "/tangent", "expected a finite non-zero direction");
        }
    }
    return m;
}

HeightField makeHeightField(const DiffractionMaterial& m) {
    if (const auto* g = std::get_if<GratingParams>(&m.heightField)) {
        return m.heightFieldType == "blazed" ? blazedGrating(*g) : sinusoidGrating(*g);
    }
    if (const auto* t = std::get_if<TrackParams>(&m.heightField)) return cdTracks(*t);
    if (const auto* r = std::get_if<RidgeParams>(&m.heightField)) return snakeRidges(*r);
    const PngField& png = std::get<PngField>(m.heightField);
    return loadHeightFieldPng(png.file, png.nmPerPixel, png.heightScaleNm);
}

StamBrdf makeBrdf(const DiffractionMaterial& m) {
    StamBrdf::Options options;
    options.terms = m.terms;
    options.tolerance = m.tolerance;
    if (m.coherenceNm) options.window = GaussianWindow{*m.coherenceNm, 4.0};
    try {
        return StamBrdf(makeHeightField(m), options);
    } catch (const TooManyTermsError& e) {
        throw MaterialError(std::string(m.terms ? "terms" : "tolerance") + ": " + e.what());
    }
}

MaterialTables buildMaterialTables(const DiffractionMaterial& m, const StamBrdf& brdf) {
    MaterialTables t;
    SpectralTables spectral = buildSpectralTables(brdf, {m.tableSize, m.wavelengthStepNm});
    if (m.path == 'a') {
        t.spectral = std::move(spectral);
    } else if (m.path == 'b') {
        t.integrated = buildIntegratedTables(spectral);
    } else {
        t.volume = buildVolumeTables(buildIntegratedTables(spectral), m.wSlices);
    }
    return t;
}

}  // namespace prism::diffraction
