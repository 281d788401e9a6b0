// prism-diffraction run as a program: the peaks --json contract against the grating equation,
// bound, and bad input (exit 2 with a message naming the problem).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>
#include <numbers>
#include <sstream>
#include <string>

#include "prism/test/run_command.hpp"

namespace {

struct Result {
    int status = -1;
    std::string output;  // stdout and stderr
};

// prism-diffraction with `args` split at spaces (no argument here contains one).
Result run(const std::string& args) {
    std::vector<std::string> command{PRISM_DIFFRACTION_CLI};
    std::istringstream words(args);
    for (std::string word; words >> word;) command.push_back(word);
    const auto r = prism::test::runCommand(command, {.workDir = {}, .mergeStderr = true});
    return {r.exitCode, r.out};
}

}  // namespace

TEST(DiffractionCli, PeaksJsonFollowsTheGratingEquation) {
    const Result r =
        run("peaks --height-field sinusoid --period-nm 2500 --amplitude-nm 150 --incidence-deg 75 "
            "--wavelengths-nm 400,550,700 --json");
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    int checked = 0;
    for (const auto& p : j.at("peaks")) {
        const double lambda = p.at("wavelength_nm"), angle = p.at("angle_deg");
        const int order = p.at("order");
        const double expected =
            std::asin(std::sin(75.0 * std::numbers::pi / 180.0) + order * lambda / 2500.0) * 180.0 / std::numbers::pi;
        EXPECT_NEAR(angle, expected, 0.05) << lambda << " nm order " << order;
        if (order == 0) {
            EXPECT_DOUBLE_EQ(p.at("relative_intensity").get<double>(), 1.0);
        }
        EXPECT_GT(p.at("relative_intensity").get<double>(), 0.0);
        ++checked;
    }
    EXPECT_GE(checked, 3 * 3);  // at least orders 0, -1, -2 for each wavelength
}

TEST(DiffractionCli, PeaksJsonKeysInContractOrder) {
    const Result r = run("peaks --period-nm 2500 --amplitude-nm 150 --incidence-deg 0 --wavelengths-nm 550 --json");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.rfind("{\"peaks\":[{\"wavelength_nm\":550", 0), 0u) << r.output;
    EXPECT_NE(r.output.find("\"order\":-1,\"angle_deg\":-12.709"), std::string::npos) << r.output;
}

TEST(DiffractionCli, ExactAndTaylorAgree) {
    const std::string args = "peaks --period-nm 2500 --amplitude-nm 150 --incidence-deg 30 --wavelengths-nm 480 --json";
    const Result taylor = run(args + " --terms 25"), exact = run(args + " --exact");
    ASSERT_EQ(taylor.status, 0);
    ASSERT_EQ(exact.status, 0);
    const auto a = nlohmann::json::parse(taylor.output).at("peaks"),
               b = nlohmann::json::parse(exact.output).at("peaks");
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].at("order"), b[i].at("order"));
        EXPECT_NEAR(a[i].at("relative_intensity").get<double>(), b[i].at("relative_intensity").get<double>(), 1e-6);
    }
}

TEST(DiffractionCli, BoundPrintsTheTermCount) {
    const Result r = run("bound --max-height-nm 150 --wavelength-nm 380 --tolerance 1e-6");
    ASSERT_EQ(r.status, 0) << r.output;
    const int n = std::stoi(r.output);
    // e^x x^(N+1)/(N+1)! with x = 4 pi 150 / 380: N meets 1e-6 and N - 1 does not.
    const double x = 4.0 * std::numbers::pi * 150.0 / 380.0;
    const auto bound = [x](int terms) { return std::exp(x + (terms + 1) * std::log(x) - std::lgamma(terms + 2.0)); };
    EXPECT_LE(bound(n), 1e-6);
    EXPECT_GT(bound(n - 1), 1e-6);
    EXPECT_EQ(run("bound --max-height-nm 0 --wavelength-nm 500 --tolerance 1e-3").output, "0\n");
}

TEST(DiffractionCli, BadInputExitsTwoWithAMessage) {
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"peaks --period-nm -2500 --wavelengths-nm 550", "--period-nm must be > 0"},
        {"peaks --amplitude-nm 20000 --wavelengths-nm 550", "more than 200 Taylor terms"},
        {"peaks --wavelengths-nm 550,950", "outside 300-900 nm"},
        {"peaks --wavelengths-nm 299", "outside 300-900 nm"},
        {"peaks --wavelengths-nm 550 --incidence-deg 95", "--incidence-deg must be in 0..89.9"},
        {"peaks --wavelengths-nm 550 --height-field png --png /nonexistent/h.png --nm-per-pixel 10 --height-scale-nm "
         "100",
         "/nonexistent/h.png: error: cannot open"},
        {"peaks --wavelengths-nm 550 --height-field plasma", "unknown --height-field"},
        {"peaks --wavelengths-nm 550 --no-such-flag", "--no-such-flag"},
        {"peaks --wavelengths-nm 550 --terms 201", "Taylor terms must be in 0..200"},
        {"bound --max-height-nm 20000 --wavelength-nm 380 --tolerance 1e-6", "more than 200 Taylor terms"},
        {"bound --max-height-nm 150 --wavelength-nm 1000 --tolerance 1e-6", "outside 300-900 nm"},
        {"bound --max-height-nm 150 --wavelength-nm 380", "--tolerance is required"},
        {"", "subcommand"},
    };
    for (const auto& c : cases) {
        const Result r = run(c.args);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    }
}

// A flag the chosen path would not use is refused, never silently ignored (issue 15).
TEST(DiffractionCli, FlagsThePathWouldNotUseAreRefused) {
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"peaks --wavelengths-nm 550 --png h.png", "--png needs --height-field png"},
        {"peaks --wavelengths-nm 550 --nm-per-pixel 10", "--nm-per-pixel needs --height-field png"},
        {"peaks --wavelengths-nm 550 --height-field cd --amplitude-nm 100", "--amplitude-nm shapes the sinusoid"},
        {"peaks --wavelengths-nm 550 --height-field snake --periods 8", "--periods shapes the sinusoid"},
        {"peaks --wavelengths-nm 550 --exact --terms 10", "--terms: --exact uses no Taylor series"},
        {"peaks --wavelengths-nm 550 --exact --tolerance 1e-3", "--tolerance: --exact uses no Taylor series"},
        {"peaks --wavelengths-nm 550 --terms 10 --tolerance 1e-3", "give one of them"},
    };
    for (const auto& c : cases) {
        const Result r = run(c.args);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    }
}

TEST(DiffractionCli, PngHeightFieldAsInTheDocs) {
    // docs/diffraction.md, "Bring your own height field": a 16-bit grey PNG of a 1400 nm
    // grating (14 px at 100 nm/px, 32 periods), read with --nm-per-pixel and --height-scale-nm.
    // Orders beyond 60 deg are not checked: there the finite patch's lobes are wide enough
    // for the G / w^2 envelope to move their maxima by more than 0.05 deg.
    std::filesystem::create_directories(PRISM_DIFFRACTION_TEST_TMP);
    const std::string path = std::string(PRISM_DIFFRACTION_TEST_TMP) + "/my_afm_scan.png";
    const int w = 448, h = 4;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<unsigned char> row(2 * w);
    for (int x = 0; x < w; ++x) {
        const int v = static_cast<int>(std::lround(32767.5 * (1.0 + std::sin(2.0 * std::numbers::pi * x / 14.0))));
        row[2 * x] = static_cast<unsigned char>(v >> 8);
        row[2 * x + 1] = static_cast<unsigned char>(v & 0xff);
    }
    for (int y = 0; y < h; ++y) png_write_row(png, row.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    const Result r = run("peaks --height-field png --png " + path +
                         " --nm-per-pixel 100 --height-scale-nm 150 --period-nm 1400 --incidence-deg 30 "
                         "--wavelengths-nm 450,550,650 --json");
    ASSERT_EQ(r.status, 0) << r.output;
    int firstOrders = 0;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    for (const auto& p : j.at("peaks")) {
        const double lambda = p.at("wavelength_nm");
        const int order = p.at("order");
        const double expected =
            std::asin(std::sin(30.0 * std::numbers::pi / 180.0) + order * lambda / 1400.0) * 180.0 / std::numbers::pi;
        if (std::abs(expected) <= 60.0) {
            EXPECT_NEAR(p.at("angle_deg").get<double>(), expected, 0.05) << lambda << " nm order " << order;
        }
        firstOrders += order == -1;
    }
    EXPECT_EQ(firstOrders, 3);
}
