// The golden-image check (prism/test/golden.hpp).
#include "prism/test/golden.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "prism/image/png_io.hpp"
#include "prism/test/env_flag.hpp"

namespace prism::test {
namespace fs = std::filesystem;

bool updatingGoldens() {
    return envFlag("PRISM_UPDATE_GOLDENS");
}

namespace {

fs::path outputDir(const GoldenCheck& check) {
    const char* dir = std::getenv("PRISM_GOLDEN_OUT");
    return (dir && *dir) ? fs::path(dir) : check.outDir;
}

// Writes the actual and the difference images; returns where, for the message.
std::string saveActualAndDiff(const GoldenCheck& check, const image::Image8& actual,
                              const image::ImageComparison& cmp) {
    const fs::path base = outputDir(check) / check.outName;
    fs::create_directories(base.parent_path());
    image::writePng(base.string() + ".actual.png", actual);
    if (cmp.sizeMatches) image::writePng(base.string() + ".diff.png", cmp.diff);
    return base.string() + (cmp.sizeMatches ? ".{actual,diff}.png" : ".actual.png");
}

GoldenVerdict compareAndSave(const image::Image8& image, const GoldenCheck& check, bool save) {
    const std::string golden = check.golden.string();
    if (!fs::exists(check.golden))
        return {GoldenOutcome::Missing, "no golden image " + golden + "; create it with PRISM_UPDATE_GOLDENS=1"};
    const image::ImageComparison cmp =
        image::compareImages(image, image::readPng(golden), check.thresholds.maxChannelDiff);
    const bool matches = image::passes(cmp, check.thresholds);
    std::string message = golden + ": " + image::describe(cmp, check.thresholds);
    if (save && (!matches || envFlag("PRISM_SAVE_ACTUAL")))
        message += "\nactual and diff images: " + saveActualAndDiff(check, image, cmp);
    return {matches ? GoldenOutcome::Matches : GoldenOutcome::Differs, message};
}

}  // namespace

GoldenVerdict compareWithGolden(const image::Image8& image, const GoldenCheck& check) {
    return compareAndSave(image, check, false);
}

GoldenVerdict checkGolden(const image::Image8& actual, const GoldenCheck& check) {
    if (updatingGoldens()) {
        fs::create_directories(check.golden.parent_path());
        image::writePng(check.golden.string(), actual);
        return {GoldenOutcome::Updated, "PRISM_UPDATE_GOLDENS: rewrote " + check.golden.string()};
    }
    return compareAndSave(actual, check, true);
}

void expectMatchesGolden(const image::Image8& actual, const GoldenCheck& check) {
    const GoldenVerdict verdict = checkGolden(actual, check);
    if (verdict.outcome == GoldenOutcome::Updated) GTEST_SKIP() << verdict.message;
    EXPECT_EQ(verdict.outcome, GoldenOutcome::Matches) << verdict.message;
}

void expectFailsGolden(const image::Image8& mutant, const GoldenCheck& check, const std::string& what) {
    if (updatingGoldens()) GTEST_SKIP() << "goldens are being rewritten";
    const GoldenVerdict verdict = compareWithGolden(mutant, check);
    EXPECT_EQ(verdict.outcome, GoldenOutcome::Differs) << what << " against " << verdict.message;
}

}  // namespace prism::test
