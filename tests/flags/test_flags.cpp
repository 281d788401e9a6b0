// Flags are never silently ignored (issue 15): every app (prism-render, prism-gallery,
// prism-agreement, prism-bluenoise, prism-diffraction, prism-rain, water, custom_flat_from_modules) runs with
// flags its mode would not use, and must exit 2 with a message naming the flag, writing
// nothing; and with the modes that do use them, and must write its files. Each case is one
// test. EveryHelpFlagHasACase reads each program's (and subcommand's) --help and fails when
// one of its flags has no case here, so a new flag needs a case. (More refusal cases sit next
// to each app's other CLI tests: tests/rendering, tests/bluenoise, tests/diffraction.)
//
// {D}, {T} and {S} in a case are as prism/test/cli_case.hpp says ({S}: examples/scenes). A
// case that reads a mask first runs the case that generates it, in the same folder.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "prism/test/cli_case.hpp"
#include "prism/test/run_command.hpp"

namespace {

// {name, program, args, exit status, stderr text, files, the case it needs}
struct Row {
    std::string name, program;
    std::vector<std::string> args;
    int exitCode;
    std::string errText;
    std::vector<std::string> files;
    std::string needs;
};

// clang-format off
const Row kRows[] = {
    {"prism_render_00", "prism-render", {"--shader", "phong", "--variant", "BLINN=1", "--mesh", "torus", "--subdiv",
     "1", "--shininess", "8", "--specular", "0.3", "--color", "1,0,0", "--light-dir", "0,-1,0", "--scale", "1,1,1",
     "--size", "32x24", "--backend", "egl", "--out", "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_render_01", "prism-render", {"--shader", "flat", "--size", "16x16", "--check-finite"}, 0, "", {}, ""},
    {"prism_render_02", "prism-render", {"--scene", "{S}/soft_shadows.json", "--size", "24x16", "--spp", "2",
     "--sampler", "white", "--frames", "2", "--out", "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_render_03", "prism-render", {"--scene", "{S}/soft_shadows.json", "--size", "24x16", "--frame", "1", "--out",
     "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_render_04", "prism-render", {"--scene", "{S}/one_light.json", "--mesh", "cube", "--out", "{D}.png"}, 2,
     "--mesh describes a --shader render", {}, ""},
    {"prism_render_05", "prism-render", {"--scene", "{S}/one_light.json", "--spp", "2", "--out", "{D}.png"}, 2,
     "no \"stochastic\"", {}, ""},
    {"prism_render_06", "prism-render", {"--scene", "{S}/soft_shadows.json", "--backend", "egl", "--out", "{D}.png"}, 2,
     "is drawn on the CPU", {}, ""},
    {"prism_render_07", "prism-render", {"--scene", "{S}/one_light.json", "--check-finite", "--out", "{D}.png"}, 2,
     "--check-finite works with --shader", {}, ""},
    {"prism_render_08", "prism-render", {"--shader", "phong", "--mesh", "cube", "--subdiv", "2", "--out", "{D}.png"}, 2,
     "--subdiv: mesh cube has no subdivision levels", {}, ""},
    {"prism_render_09", "prism-render", {"--shader", "phong", "--sampler", "white", "--out", "{D}.png"}, 2,
     "only with --scene", {}, ""},
    {"prism_bluenoise_generate_10", "prism-bluenoise generate", {"--size", "16x16", "--depth", "1", "--sigma", "1.5",
     "--seed", "2", "--bits", "8", "--out", "{T}/mask.png"}, 0, "", {"{T}/mask.png"}, ""},
    {"prism_bluenoise_generate_11", "prism-bluenoise generate", {"--size", "8x8", "--depth", "2", "--spatiotemporal",
     "--sigma-time", "1.5", "--out", "{D}"}, 0, "", {"{D}/slice_001.png"}, ""},
    {"prism_bluenoise_generate_12", "prism-bluenoise generate", {"--size", "8x8", "--sigma-time", "1.5", "--out",
     "{D}.png"}, 2, "--sigma-time needs --spatiotemporal", {}, ""},
    {"prism_bluenoise_measure_13", "prism-bluenoise measure", {"{T}/mask.png", "--json", "--spectrum-svg", "{D}.svg"},
     0, "", {"{D}.svg"}, "prism_bluenoise_generate_10"},
    {"prism_bluenoise_render_14", "prism-bluenoise render", {"--sampler", "sorted", "--spp", "1", "--frames", "2",
     "--size", "16x16", "--mask-size", "16", "--block", "4", "--schedule", "inverse", "--epochs", "1",
     "--retarget-cache", "{D}.bin", "--scene", "black", "--out", "{D}.png"}, 0, "", {"{D}.png", "{D}.bin"}, ""},
    {"prism_bluenoise_render_15", "prism-bluenoise render", {"--sampler", "stack", "--stack-depth", "2", "--mask-size",
     "8", "--size", "8x8", "--frame", "1", "--out", "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_bluenoise_render_16", "prism-bluenoise render", {"--sampler", "sorted", "--a-posteriori", "--size", "8x8",
     "--out", "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_bluenoise_render_17", "prism-bluenoise render", {"--sampler", "sorted", "--no-retarget", "--frames", "2",
     "--size", "8x8", "--out", "{D}.png"}, 0, "", {"{D}.png"}, ""},
    {"prism_bluenoise_render_18", "prism-bluenoise render", {"--reference", "4", "--size", "8x8", "--out", "{D}.png"},
     0, "", {"{D}.png"}, ""},
    {"prism_bluenoise_render_19", "prism-bluenoise render", {"--reference", "4", "--sampler", "white", "--out",
     "{D}.png"}, 2, "--sampler: --reference renders", {}, ""},
    {"prism_bluenoise_render_20", "prism-bluenoise render", {"--sampler", "white", "--block", "8", "--out", "{D}.png"},
     2, "--block: only for --sampler sorted", {}, ""},
    {"prism_bluenoise_render_21", "prism-bluenoise render", {"--sampler", "white", "--mask-size", "8", "--out",
     "{D}.png"}, 2, "--mask-size: the white sampler uses no mask", {}, ""},
    {"prism_bluenoise_render_22", "prism-bluenoise render", {"--sampler", "bluenoise", "--stack-depth", "2", "--out",
     "{D}.png"}, 2, "--stack-depth: only for --sampler stack", {}, ""},
    {"prism_bluenoise_render_23", "prism-bluenoise render", {"--sampler", "sorted", "--epochs", "2", "--out",
     "{D}.png"}, 2, "--epochs: this render does not retarget", {}, ""},
    {"prism_bluenoise_render_24", "prism-bluenoise render", {"--frame", "1", "--frames", "2", "--out", "{D}.png"}, 2,
     "--frame: --frames K renders the mean", {}, ""},
    {"prism_diffraction_peaks_25", "prism-diffraction peaks", {"--height-field", "blazed", "--period-nm", "2500",
     "--amplitude-nm", "100", "--incidence-deg", "10", "--wavelengths-nm", "550", "--terms", "12", "--periods", "8",
     "--samples-per-period", "16", "--json"}, 0, "", {}, ""},
    {"prism_diffraction_peaks_26", "prism-diffraction peaks", {"--periods", "8", "--samples-per-period", "16",
     "--wavelengths-nm", "550", "--tolerance", "1e-3"}, 0, "", {}, ""},
    {"prism_diffraction_peaks_27", "prism-diffraction peaks", {"--periods", "8", "--samples-per-period", "16",
     "--wavelengths-nm", "550", "--exact"}, 0, "", {}, ""},
    {"prism_diffraction_peaks_28", "prism-diffraction peaks", {"--height-field", "png", "--png", "{T}/mask.png",
     "--nm-per-pixel", "200", "--height-scale-nm", "50", "--wavelengths-nm", "550"}, 0, "", {},
     "prism_bluenoise_generate_10"},
    {"prism_diffraction_peaks_29", "prism-diffraction peaks", {"--wavelengths-nm", "550", "--png", "{T}/mask.png"}, 2,
     "--png needs --height-field png", {}, "prism_bluenoise_generate_10"},
    {"prism_diffraction_peaks_30", "prism-diffraction peaks", {"--wavelengths-nm", "550", "--height-field", "cd",
     "--amplitude-nm", "9"}, 2, "--amplitude-nm shapes the sinusoid", {}, ""},
    {"prism_diffraction_peaks_31", "prism-diffraction peaks", {"--wavelengths-nm", "550", "--exact", "--terms", "9"}, 2,
     "--terms: --exact uses no Taylor series", {}, ""},
    {"prism_diffraction_bound_32", "prism-diffraction bound", {"--max-height-nm", "150", "--wavelength-nm", "380",
     "--tolerance", "1e-6"}, 0, "", {}, ""},
    {"prism_gallery_33", "prism-gallery", {"--out", "{D}", "--size", "16", "--backend", "egl"}, 0, "",
     {"{D}/gallery.png", "{D}/catalogue.tsv"}, ""},
    {"prism_gallery_34", "prism-gallery", {"--out", "{D}", "--backend", "glfw"}, 2,
     "--backend glfw: expected egl or osmesa", {}, ""},
    {"prism_gallery_35", "prism-gallery", {"--out", "{D}", "--size", "8"}, 2, "--size", {}, ""},
    {"prism_gallery_36", "prism-gallery", {"--out", "{D}", "--bogus"}, 2, "--bogus", {}, ""},
    {"prism_rain_37", "prism-rain", {"--view", "1", "--intensity", "heavy", "--wind", "2", "--wind-direction", "90",
     "--fog", "--fog-strength", "0.3", "--technique", "points", "--seed", "4", "--width", "32", "--height", "32",
     "--warmup", "1", "--out", "{D}"}, 0, "", {"{D}/rain.png"}, ""},
    {"prism_rain_38", "prism-rain", {"--sequence", "3", "--width", "32", "--height", "24", "--warmup", "1", "--out",
     "{D}"}, 0, "", {"{D}/frame_00.png", "{D}/frame_02.png", "{D}/sequence.png"}, ""},
    {"prism_rain_39", "prism-rain", {"--intensity", "heavy", "--out", "{D}"}, 2,
     "--intensity needs --view, --sequence or --window", {}, ""},
    {"prism_rain_40", "prism-rain", {"--wind", "3", "--out", "{D}"}, 2, "--wind needs --view", {}, ""},
    {"prism_rain_41", "prism-rain", {"--fog", "--out", "{D}"}, 2, "--fog needs --view", {}, ""},
    {"prism_rain_42", "prism-rain", {"--view", "0", "--fog-strength", "0.3", "--out", "{D}"}, 2,
     "--fog-strength needs --fog", {}, ""},
    {"prism_rain_43", "prism-rain", {"--frames", "3", "--out", "{D}"}, 2, "--frames needs --window", {}, ""},
    {"prism_rain_44", "prism-rain", {"--demo-keys", "--out", "{D}"}, 2, "--demo-keys needs --window", {}, ""},
    {"prism_rain_45", "prism-rain", {"--window", "--sequence", "2"}, 2, "--sequence does not apply to --window", {},
     ""},
    {"prism_rain_46", "prism-rain", {"--window", "--out", "{D}"}, 2, "--out does not apply to --window", {}, ""},
    {"prism_rain_47", "prism-rain", {"--window", "--view", "0"}, 2, "--view does not apply to --window", {}, ""},
    {"prism_rain_48", "prism-rain", {"--window", "--warmup", "3"}, 2, "--warmup does not apply to --window", {}, ""},
    {"prism_rain_49", "prism-rain", {"--window", "--intensity", "0.5"}, 2,
     "with --window, --intensity must name a class", {}, ""},
    {"prism_rain_50", "prism-rain", {"--sequence", "0", "--out", "{D}"}, 2, "--sequence", {}, ""},
    {"water_51", "water", {"--sequence", "3", "--grid", "16", "--cell", "0.5", "--steps", "6", "--dt", "1", "--rain",
     "heavy", "--fog", "0.01", "--width", "32", "--height", "24", "--out", "{D}"}, 0, "", {"{D}/frame_00.png",
     "{D}/frame_02.png", "{D}/sequence.png"}, ""},
    {"water_52", "water", {"--grid", "16", "--steps", "2", "--gpu", "--width", "32", "--height", "24", "--out", "{D}"},
     0, "", {"{D}/overview.png", "{D}/depth.png"}, ""},
    {"water_53", "water", {"--grid", "16", "--frames", "3", "--out", "{D}"}, 2, "--frames needs --window", {}, ""},
    {"water_54", "water", {"--grid", "16", "--steps", "2", "--fog", "0.02", "--fog-billboards", "0.5", "--width", "32",
     "--height", "24", "--out", "{D}"}, 0, "", {"{D}/overview.png", "{D}/ground.png"}, ""},
    {"water_55", "water", {"--grid", "16", "--fog-billboards", "0.5", "--out", "{D}"}, 2,
     "--fog-billboards needs --fog", {}, ""},
    {"water_56", "water", {"--grid", "16", "--height-scale", "3", "--out", "{D}"}, 2,
     "--height-scale needs --heightmap", {}, ""},
    {"water_57", "water", {"--grid", "16", "--permeability-max", "5", "--out", "{D}"}, 2,
     "--permeability-max needs --permeability", {}, ""},
    {"water_58", "water", {"--heightmap", "h.png", "--grid", "16", "--out", "{D}"}, 2, "does not apply to --heightmap",
     {}, ""},
    {"water_59", "water", {"--permeability", "p.png", "--grid", "16", "--out", "{D}"}, 1, "p.png", {}, ""},
    {"water_60", "water", {"--window", "--steps", "3"}, 2, "--steps does not apply to --window", {}, ""},
    {"water_61", "water", {"--window", "--out", "{D}"}, 2, "--out does not apply to --window", {}, ""},
    {"water_62", "water", {"--window", "--sequence", "2"}, 2, "--sequence does not apply to --window", {}, ""},
    {"water_63", "water", {"--window", "--dt", "2"}, 2, "--dt with --window needs --frames", {}, ""},
    // The report's live blue-noise view takes one frame of the white or bluenoise sampler (docs/web.md).
    {"prism_bluenoise_render_live_record", "prism-bluenoise render", {"--sampler", "bluenoise", "--size", "8x8",
     "--mask-size", "8", "--live-record", "{D}.json", "--out", "{D}.png"}, 0, "", {"{D}.png", "{D}.json"}, ""},
    {"prism_bluenoise_render_live_record_sorted", "prism-bluenoise render", {"--sampler", "sorted", "--size", "8x8",
     "--live-record", "{D}.json", "--out", "{D}.png"}, 2, "--live-record: the live view draws one frame", {}, ""},
    // An example program: an argument it would not use is a usage error.
    {"custom_flat_rejects_two_paths", "custom_flat_from_modules", {"a.png", "b.png"}, 2, "usage", {}, ""},
    {"custom_flat_rejects_size", "custom_flat_from_modules", {"--size"}, 2, "usage", {}, ""},
    // water's guard rails: a non-finite or overflowing number is a usage error, nothing written.
    {"water_rejects_rain_1e46", "water", {"--grid", "32", "--steps", "20", "--rain", "1e46", "--out", "{D}"}, 2,
     "error:", {}, ""},
    {"water_rejects_rain_inf", "water", {"--grid", "32", "--steps", "20", "--rain", "inf", "--out", "{D}"}, 2, "error:",
     {}, ""},
    {"water_rejects_dt_nan", "water", {"--grid", "32", "--steps", "20", "--dt", "nan", "--out", "{D}"}, 2, "error:", {},
     ""},
    {"water_rejects_dt_1e300", "water", {"--grid", "32", "--steps", "20", "--dt", "1e300", "--out", "{D}"}, 2, "error:",
     {}, ""},
    {"water_rejects_cell_1e_30", "water", {"--grid", "32", "--steps", "20", "--cell", "1e-30", "--out", "{D}"}, 2,
     "error:", {}, ""},
    {"water_rejects_cell_inf", "water", {"--grid", "32", "--steps", "20", "--cell", "inf", "--out", "{D}"}, 2, "error:",
     {}, ""},
    {"water_rejects_height_scale_inf", "water", {"--grid", "32", "--steps", "20", "--height-scale", "inf", "--out",
     "{D}"}, 2, "error:", {}, ""},
    {"water_rejects_fog_billboards_nan", "water", {"--grid", "32", "--steps", "20", "--fog", "0.01", "--fog-billboards",
     "nan", "--out", "{D}"}, 2, "error:", {}, ""},
    {"prism_agreement_writes_its_table", "prism-agreement", {"--out", "{D}", "--size", "16"}, 0, "",
     {"{D}/agreement.tsv", "{D}/agreement-pair.png"}, ""},
    {"prism_agreement_rejects_size_8", "prism-agreement", {"--out", "{D}", "--size", "8"}, 2, "--size", {}, ""},
    {"prism_agreement_rejects_bogus", "prism-agreement", {"--out", "{D}", "--bogus"}, 2, "--bogus", {}, ""},
};
// clang-format on

std::vector<prism::test::CliCase> cases() {
    std::vector<prism::test::CliCase> cases;
    for (const Row& r : kRows)
        cases.push_back({.name = r.name,
                         .program = r.program,
                         .args = r.args,
                         .exitCode = r.exitCode,
                         .errText = r.errText,
                         .files = r.files,
                         .needs = r.needs,
                         .outRegex = "",
                         .errRegex = ""});
    return cases;
}
const std::vector<prism::test::CliCase> kCases = cases();

// The built apps, from PRISM_FLAGS_APPS ("name=path|name=path|"); an app not built has no entry.
std::map<std::string, std::string> builtApps() {
    std::map<std::string, std::string> apps;
    std::istringstream list(PRISM_FLAGS_APPS);
    for (std::string entry; std::getline(list, entry, '|');)
        if (const auto eq = entry.find('='); eq != std::string::npos) apps[entry.substr(0, eq)] = entry.substr(eq + 1);
    return apps;
}

const prism::test::CliSuite kSuite{
    .root = PRISM_FLAGS_TEST_TMP, .apps = builtApps(), .cases = kCases, .scenes = PRISM_SCENES_DIR};

class UsedOrRefused : public ::testing::TestWithParam<prism::test::CliCase> {};

TEST_P(UsedOrRefused, Case) {
    prism::test::checkCliCase(kSuite, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Flags, UsedOrRefused, ::testing::ValuesIn(prism::test::runnableCases(kSuite)),
                         prism::test::caseName);

// The long flags a CLI11 program (or subcommand) lists in --help, without --help itself.
std::set<std::string> helpFlags(const std::vector<std::string>& cmd) {
    std::vector<std::string> help = cmd;
    help.push_back("--help");
    std::istringstream out(prism::test::runCommand(help).out);
    static const std::regex flag(R"(^\s+(?:-\w,)?(--[\w-]+))");
    std::set<std::string> flags;
    std::smatch m;
    for (std::string line; std::getline(out, line);)
        if (std::regex_search(line, m, flag) && m[1] != "--help") flags.insert(m[1]);
    return flags;
}

TEST(Flags, EveryHelpFlagHasACase) {
    std::set<std::string> programs;
    for (const auto& c : kCases) programs.insert(c.program);
    int checked = 0;
    for (const auto& program : programs) {
        const auto cmd = prism::test::appCommand(kSuite, program);
        if (cmd.empty()) continue;
        std::set<std::string> covered;
        for (const auto& c : kCases)
            if (c.program == program)
                for (const auto& a : c.args)
                    if (a.rfind("--", 0) == 0) covered.insert(a);
        for (const auto& flag : helpFlags(cmd))
            EXPECT_TRUE(covered.count(flag))
                << program << " " << flag
                << ": no case in tests/flags/test_flags.cpp (add one that uses or refuses it)";
        ++checked;
    }
    EXPECT_GT(checked, 0) << "no app built";
}

TEST(Flags, EveryBuiltAppHasCases) {
    for (const auto& [app, path] : kSuite.apps) {
        bool found = false;
        for (const auto& c : kCases) found = found || c.program.rfind(app, 0) == 0;
        EXPECT_TRUE(found) << app << " (" << path << "): no cases";
    }
}

}  // namespace
