// The one golden-image check of Prism's tests, and the one place that reads the update
// switch (its name and use: tests/golden/README.md; golden.cpp reads it): compare a
// rendered image with its committed PNG within stated thresholds; on failure (or with
// PRISM_SAVE_ACTUAL=1) write the actual image and an amplified difference under
// PRISM_GOLDEN_OUT (else the test's own output folder); in update mode write the golden
// instead and report the test skipped, so an update run never passes a comparison it has
// just made true.
//
//     #include "prism/test/golden.hpp"
//
//     TEST(MyShader, MatchesItsGolden) {
//         const prism::image::Image8 actual = renderMyShader();
//         prism::test::expectMatchesGolden(actual, {.golden = "tests/golden/mine/sphere.png",
//                                                   .outName = "mine/sphere",
//                                                   .thresholds = {.maxChannelDiff = 3, .maxShareOver = 0.001},
//                                                   .outDir = "build/golden-failures"});
//     }
#pragma once

#include <filesystem>
#include <string>

#include "prism/image/image.hpp"
#include "prism/image/image_compare.hpp"

namespace prism::test {

struct GoldenCheck {
    std::filesystem::path golden;  // the committed PNG
    std::string outName;           // actual/diff images go to <out>/<outName>.{actual,diff}.png
    image::Thresholds thresholds;  // what "matches" means for this case (state them beside the case)
    std::filesystem::path outDir;  // <out> when PRISM_GOLDEN_OUT is not set
};

enum class GoldenOutcome { Matches, Differs, Missing, Updated };

struct GoldenVerdict {
    GoldenOutcome outcome = GoldenOutcome::Differs;
    std::string message;  // the golden's path, the statistics against the thresholds, where the images went
};

// True when this run rewrites goldens (the update switch set to anything but "", "0",
// "false", "off"): a test whose other checks read the goldens skips them then.
bool updatingGoldens();

// Compares only (never writes): Matches, Differs, or Missing with how to create the golden.
GoldenVerdict compareWithGolden(const image::Image8& image, const GoldenCheck& check);

// The check without gtest: in update mode writes the golden (Updated); else
// compareWithGolden(), writing the actual and diff images when it differs.
GoldenVerdict checkGolden(const image::Image8& actual, const GoldenCheck& check);

// checkGolden() in a test: a failure for Differs and Missing, a skip for Updated. Call it
// last in the test body (the skip returns from this function only).
void expectMatchesGolden(const image::Image8& actual, const GoldenCheck& check);

// The mutation check of a golden: `mutant` (the rendering with one thing changed, named by
// `what`) must differ from the golden beyond its thresholds; a missing golden fails, and in
// update mode the check is skipped (the goldens are being rewritten).
void expectFailsGolden(const image::Image8& mutant, const GoldenCheck& check, const std::string& what);

}  // namespace prism::test
