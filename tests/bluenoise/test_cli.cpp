// prism-bluenoise run as a program: each case checks the exit status (0, 1 for an unreadable
// file, 2 for a usage error), a regex over stdout or stderr, and the files a run must write.
// A case that measures a mask first runs the case that generates it, in its own folder, so
// every case stands alone and cases run in parallel (prism/test/cli_case.hpp; {T} is the
// case's folder).
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "prism/test/cli_case.hpp"

namespace {

// {name, exit status, args, stdout regex, stderr regex, files, the case it needs}
struct Row {
    Row(std::string name, int exitCode, std::vector<std::string> args, std::string outRegex = "",
        std::string errRegex = "", std::vector<std::string> files = {}, std::string needs = "")
        : name(std::move(name)),
          exitCode(exitCode),
          args(std::move(args)),
          outRegex(std::move(outRegex)),
          errRegex(std::move(errRegex)),
          files(std::move(files)),
          needs(std::move(needs)) {}
    std::string name;
    int exitCode;
    std::vector<std::string> args;
    std::string outRegex, errRegex;
    std::vector<std::string> files;
    std::string needs;
};

// clang-format off
const Row kRows[] = {
    {"generate_128", 0, {"generate", "--size", "128x128", "--seed", "3", "--out", "{T}/mask128.png"}, "", "",
     {"{T}/mask128.png"}},
    {"measure_128_text", 0, {"measure", "{T}/mask128.png"},
     "histogram_uniform: true\nlow_frequency_power_ratio: 0\\.00[0-9]+.*\nfiltered_error_sigma1: 0\\.0[0-4]", "", {},
     "generate_128"},
    {"measure_128_json_svg", 0, {"measure", "{T}/mask128.png", "--json", "--spectrum-svg", "{T}/spectrum128.svg"},
     "^\\{\"file\": .*\"histogram_uniform\": true, \"low_frequency_power_ratio\": [0-9.e-]+, "
     "\"filtered_error_sigma1\": 0\\.0[0-4][0-9]*, \"anisotropy\": [-0-9.e]+\\}",
     "", {"{T}/spectrum128.svg"}, "generate_128"},
    {"generate_depth_16bit", 0,
     {"generate", "--size", "64x32", "--depth", "3", "--bits", "16", "--sigma", "1.9", "--seed", "1", "--out",
      "{T}/stack"},
     "", "", {"{T}/stack/slice_000.png", "{T}/stack/slice_001.png", "{T}/stack/slice_002.png"}},
    {"measure_slice_16bit", 0, {"measure", "{T}/stack/slice_002.png"}, "64x32, 16 bit\\)\nhistogram_uniform: true", "",
     {}, "generate_depth_16bit"},
    {"generate_spatiotemporal", 0,
     {"generate", "--size", "32x16", "--depth", "4", "--spatiotemporal", "--sigma-time", "1.5", "--out", "{T}/stbn"},
     "", "", {"{T}/stbn/slice_000.png", "{T}/stbn/slice_003.png"}},
    {"measure_spatiotemporal_slice", 0, {"measure", "{T}/stbn/slice_003.png"}, "histogram_uniform: true", "", {},
     "generate_spatiotemporal"},
    {"usage_spatiotemporal_too_deep", 2,
     {"generate", "--size", "8x8", "--depth", "300", "--spatiotemporal", "--out", "{T}/deep"}, "", "up to 256"},
    {"generate_1x1", 0, {"generate", "--size", "1x1", "--out", "{T}/one.png"}, "", "", {"{T}/one.png"}},
    {"generate_1xN_not_multiple_of_256", 0, {"generate", "--size", "1x300", "--out", "{T}/line.png"}},
    {"usage_unknown_flag", 2, {"generate", "--size", "8x8", "--out", "{T}/x.png", "--bogus"}, "", "bogus"},
    {"usage_bad_size", 2, {"generate", "--size", "513x4", "--out", "{T}/x.png"}, "", "--size '513x4'"},
    {"usage_size_not_wxh", 2, {"generate", "--size", "8", "--out", "{T}/x.png"}, "", "WxH"},
    {"usage_missing_out", 2, {"generate", "--size", "8x8"}, "", "--out"},
    {"usage_bits_12", 2, {"generate", "--size", "8x8", "--bits", "12", "--out", "{T}/x.png"}},
    {"usage_no_subcommand", 2, {}},
    {"usage_depth_1001", 2, {"generate", "--size", "4x4", "--depth", "1001", "--out", "{T}/d"}, "", "depth"},
    {"usage_sigma_0", 2, {"generate", "--size", "4x4", "--sigma", "0", "--out", "{T}/s.png"}, "", "sigma"},
    {"usage_render_spp_0", 2, {"render", "--spp", "0", "--out", "{T}/x.png"}, "", "spp"},
    {"generate_depth_1000_tiny", 0, {"generate", "--size", "1x1", "--depth", "1000", "--out", "{T}/d1000"}, "", "",
     {"{T}/d1000/slice_999.png"}},
    {"render_bluenoise", 0,
     {"render", "--sampler", "bluenoise", "--size", "48x32", "--spp", "2", "--frame", "5", "--out",
      "{T}/render_blue.png"},
     "", "", {"{T}/render_blue.png"}},
    {"render_sorted_frames_cached", 0,
     {"render", "--sampler", "sorted", "--size", "32x32", "--frames", "4", "--mask-size", "32", "--block", "4",
      "--schedule", "inverse", "--epochs", "4", "--retarget-cache", "{T}/retarget.bin", "--out",
      "{T}/render_sorted.png"},
     "", "", {"{T}/render_sorted.png", "{T}/retarget.bin"}},
    {"render_stack", 0,
     {"render", "--sampler", "stack", "--mask-size", "16", "--stack-depth", "4", "--size", "32x32", "--frames", "6",
      "--out", "{T}/render_stack.png"},
     "", "", {"{T}/render_stack.png"}},
    {"render_white_scene_frame_million", 0,
     {"render", "--scene", "white", "--sampler", "white", "--size", "16x16", "--frame", "1000000", "--out",
      "{T}/render_white.png"}},
    {"render_reference_black", 0,
     {"render", "--scene", "black", "--reference", "16", "--size", "16x16", "--out", "{T}/render_black.png"}},
    {"usage_render_bad_sampler", 2, {"render", "--sampler", "gray", "--out", "{T}/x.png"}, "", "gray"},
    {"usage_render_block_5", 2, {"render", "--block", "5", "--out", "{T}/x.png"}},
    // Flags are used or refused, never ignored (issue 15).
    {"usage_render_block_without_sorted", 2, {"render", "--sampler", "white", "--block", "8", "--out", "{T}/x.png"},
     "", "--block: only for --sampler sorted"},
    {"usage_render_reference_with_spp", 2, {"render", "--reference", "16", "--spp", "4", "--out", "{T}/x.png"}, "",
     "--spp: --reference renders the stratified reference"},
    {"usage_render_stack_depth_without_stack", 2,
     {"render", "--sampler", "bluenoise", "--stack-depth", "4", "--out", "{T}/x.png"}, "",
     "--stack-depth: only for --sampler stack"},
    {"usage_render_mask_size_white", 2, {"render", "--sampler", "white", "--mask-size", "32", "--out", "{T}/x.png"},
     "", "--mask-size: the white sampler uses no mask"},
    {"usage_render_retarget_cache_frame_0", 2,
     {"render", "--sampler", "sorted", "--retarget-cache", "{T}/r.bin", "--out", "{T}/x.png"}, "",
     "--retarget-cache: this render does not retarget"},
    {"usage_render_no_retarget_a_posteriori", 2,
     {"render", "--sampler", "sorted", "--no-retarget", "--a-posteriori", "--out", "{T}/x.png"}, "",
     "--a-posteriori never retargets"},
    {"usage_render_frame_and_frames", 2, {"render", "--frame", "3", "--frames", "4", "--out", "{T}/x.png"}, "",
     "--frame: --frames K renders the mean"},
    {"usage_generate_sigma_time_alone", 2, {"generate", "--size", "8x8", "--sigma-time", "2", "--out", "{T}/x.png"},
     "", "--sigma-time needs --spatiotemporal"},
    {"usage_render_sorted_far_frame", 2, {"render", "--sampler", "sorted", "--frame", "1000000", "--out", "{T}/x.png"},
     "", "replays every frame"},
    {"measure_missing_file", 1, {"measure", "{T}/does-not-exist.png"}, "",
     "does-not-exist.png: error: cannot read PNG"},
};
// clang-format on

std::vector<prism::test::CliCase> cases() {
    std::vector<prism::test::CliCase> cases;
    for (const Row& r : kRows)
        cases.push_back({.name = r.name,
                         .program = "prism-bluenoise",
                         .args = r.args,
                         .exitCode = r.exitCode,
                         .errText = "",
                         .files = r.files,
                         .needs = r.needs,
                         .outRegex = r.outRegex,
                         .errRegex = r.errRegex});
    return cases;
}

const prism::test::CliSuite kSuite{.root = PRISM_BLUENOISE_TEST_TMP,
                                   .apps = {{"prism-bluenoise", PRISM_BLUENOISE_CLI}},
                                   .cases = cases(),
                                   .scenes = ""};

class BluenoiseCli : public ::testing::TestWithParam<prism::test::CliCase> {};

TEST_P(BluenoiseCli, Runs) {
    prism::test::checkCliCase(kSuite, GetParam());
}

INSTANTIATE_TEST_SUITE_P(, BluenoiseCli, ::testing::ValuesIn(prism::test::runnableCases(kSuite)),
                         prism::test::caseName);

}  // namespace
