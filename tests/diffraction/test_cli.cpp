// prism-diffraction run as a program: the peaks --json contract against the grating equation,
// bound, and bad input (exit 2 with a message naming the problem).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace {

struct Result {
    int status = -1;
    std::string output;  // stdout and stderr
};

Result run(const std::string& args) {
    Result r;
    const std::string command = std::string(PRISM_DIFFRACTION_CLI) + " " + args + " 2>&1";
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
    const int status = pclose(pipe);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

}  // namespace

TEST(DiffractionCli, PeaksJsonFollowsTheGratingEquation) {
    const Result r = run("peaks --height-field sinusoid --period-nm 2500 --amplitude-nm 150 --incidence-deg 75 "
                         "--wavelengths-nm 400,550,700 --json");
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);
    int checked = 0;
    for (const auto& p : j.at("peaks")) {
        const double lambda = p.at("wavelength_nm"), angle = p.at("angle_deg");
        const int order = p.at("order");
        const double expected = std::asin(std::sin(75.0 * std::numbers::pi / 180.0) + order * lambda / 2500.0) * 180.0 / std::numbers::pi;
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
    const auto a = nlohmann::json::parse(taylor.output).at("peaks"), b = nlohmann::json::parse(exact.output).at("peaks");
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
        {"peaks --wavelengths-nm 550 --height-field png --png /nonexistent/h.png --nm-per-pixel 10 --height-scale-nm 100",
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
