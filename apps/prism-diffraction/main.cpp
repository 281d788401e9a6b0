// prism-diffraction: the diffraction reference on the command line (docs/diffraction.md).
//   prism-diffraction peaks --height-field sinusoid --period-nm 2500 --amplitude-nm 150
//                           --incidence-deg 0 --wavelengths-nm 400,550,700 [--terms N] [--exact] [--json]
//     samples the reference BRDF in the plane of incidence (theta in degrees from the normal,
//     positive on the specular side), refines each maximum to < 0.001 deg and prints its order m
//     (sin theta = sin T + m lambda / d), angle and intensity relative to order 0.
//   prism-diffraction bound --max-height-nm 150 --wavelength-nm 380 --tolerance 1e-6
//     prints the number of Taylor terms N the thesis's error bound e^x x^(N+1)/(N+1)! requires.
// A flag the chosen path does not use (--png without --height-field png, --amplitude-nm
// for the cd or snake fields, --terms or --tolerance with --exact, --tolerance with
// --terms) is refused with exit 2, never silently ignored.
// Bad input (negative period, heights needing N > 200, wavelengths outside 300-900 nm, an
// unreadable PNG, unknown flags) prints "prism-diffraction: error: ..." and exits 2.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "prism/diffraction/peaks.hpp"
#include "prism/diffraction/taylor_bound.hpp"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 2;

struct UsageError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

struct PeaksArgs {
    std::string heightField = "sinusoid";
    double periodNm = 2500.0;
    double amplitudeNm = 150.0;
    double incidenceDeg = 0.0;
    std::vector<double> wavelengthsNm;
    std::optional<int> terms;
    double tolerance = 1e-6;
    bool exact = false;
    bool json = false;
    int periods = 64;
    int samplesPerPeriod = 32;
    std::string png;
    double nmPerPixel = 0.0;
    double heightScaleNm = 0.0;
};

struct BoundArgs {
    double maxHeightNm = 0.0;
    double wavelengthNm = 0.0;
    double tolerance = 0.0;
};

// A number as a person would write it: 2500, 0.5, 1e-06.
std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

void checkWavelength(double lambda, const std::string& flag) {
    if (!(std::isfinite(lambda) && lambda >= 300.0 && lambda <= 900.0)) {
        throw UsageError(flag + " " + number(lambda) + " nm is outside 300-900 nm");
    }
}

prism::diffraction::HeightField makeField(const PeaksArgs& a) {
    using namespace prism::diffraction;
    if (!(std::isfinite(a.periodNm) && a.periodNm > 0.0)) {
        throw UsageError("--period-nm must be > 0 (got " + number(a.periodNm) + ")");
    }
    if (!(std::isfinite(a.amplitudeNm) && a.amplitudeNm >= 0.0)) {
        throw UsageError("--amplitude-nm must be >= 0 (got " + number(a.amplitudeNm) + ")");
    }
    const GratingParams grating{a.periodNm, a.amplitudeNm, a.periods, a.samplesPerPeriod};
    if (a.heightField == "sinusoid") return sinusoidGrating(grating);
    if (a.heightField == "blazed") return blazedGrating(grating);
    if (a.heightField == "cd") return cdTracks({});
    if (a.heightField == "snake") return snakeRidges({});
    if (a.heightField == "png") {
        if (a.png.empty()) throw UsageError("--height-field png needs --png FILE");
        if (!(a.nmPerPixel > 0.0)) throw UsageError("--height-field png needs --nm-per-pixel > 0");
        if (!(a.heightScaleNm >= 0.0)) throw UsageError("--height-field png needs --height-scale-nm >= 0");
        try {
            return loadHeightFieldPng(a.png, a.nmPerPixel, a.heightScaleNm);
        } catch (const std::runtime_error& e) {
            throw UsageError(e.what());
        }
    }
    throw UsageError("unknown --height-field '" + a.heightField + "' (sinusoid, blazed, cd, snake or png)");
}

int runPeaks(const PeaksArgs& a) {
    using namespace prism::diffraction;
    if (a.wavelengthsNm.empty()) throw UsageError("--wavelengths-nm needs at least one wavelength");
    for (double lambda : a.wavelengthsNm) checkWavelength(lambda, "--wavelengths-nm");
    if (!(a.incidenceDeg >= 0.0 && a.incidenceDeg <= 89.9)) {
        throw UsageError("--incidence-deg must be in 0..89.9 (got " + number(a.incidenceDeg) + ")");
    }
    StamBrdf::Options options;
    options.path = a.exact ? StamBrdf::Path::Exact : StamBrdf::Path::Taylor;
    options.terms = a.terms;
    options.tolerance = a.tolerance;
    std::optional<StamBrdf> brdf;
    try {
        brdf.emplace(makeField(a), options);
    } catch (const TooManyTermsError& e) {
        throw UsageError(e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    std::vector<Peak> peaks = findPeaks(*brdf, {a.incidenceDeg, a.wavelengthsNm, a.periodNm});
    for (Peak& p : peaks) {
        p.angleDeg = std::round(p.angleDeg * 1e4) / 1e4;
        if (p.angleDeg == 0.0) p.angleDeg = 0.0;  // no "-0"
    }
    if (a.json) {
        nlohmann::ordered_json out = {{"peaks", nlohmann::ordered_json::array()}};
        for (const Peak& p : peaks) {
            out["peaks"].push_back({{"wavelength_nm", p.wavelengthNm},
                                    {"order", p.order},
                                    {"angle_deg", p.angleDeg},
                                    {"relative_intensity", p.relativeIntensity}});
        }
        std::cout << out.dump() << "\n";
        return kExitOk;
    }
    std::printf("# %s d = %g nm, A = %g nm, incidence %g deg, %s\n", a.heightField.c_str(), a.periodNm, a.amplitudeNm,
                a.incidenceDeg, a.exact ? "exact path" : ("Taylor path, N = " + std::to_string(brdf->terms())).c_str());
    std::printf("%13s %6s %11s %19s\n", "wavelength_nm", "order", "angle_deg", "relative_intensity");
    for (const Peak& p : peaks) {
        std::printf("%13g %6d %11.4f %19.6g\n", p.wavelengthNm, p.order, p.angleDeg, p.relativeIntensity);
    }
    return kExitOk;
}

// Throws UsageError naming a given flag that this peaks run would not use.
void refuseUnusedPeaksFlags(const CLI::App& cmd, const PeaksArgs& a) {
    auto given = [&cmd](const char* flag) { return cmd.count(flag) > 0; };
    if (a.heightField != "png")
        for (const char* f : {"--png", "--nm-per-pixel", "--height-scale-nm"})
            if (given(f)) throw UsageError(std::string(f) + " needs --height-field png");
    if (a.heightField != "sinusoid" && a.heightField != "blazed")
        for (const char* f : {"--amplitude-nm", "--periods", "--samples-per-period"})
            if (given(f))
                throw UsageError(std::string(f) + " shapes the sinusoid and blazed gratings, not --height-field " +
                                 a.heightField);
    if (a.exact)
        for (const char* f : {"--terms", "--tolerance"})
            if (given(f)) throw UsageError(std::string(f) + ": --exact uses no Taylor series");
    if (given("--terms") && given("--tolerance"))
        throw UsageError("--tolerance picks N only when --terms is not given; give one of them");
}

int runBound(const BoundArgs& a) {
    checkWavelength(a.wavelengthNm, "--wavelength-nm");
    try {
        std::printf("%d\n", prism::diffraction::termsForTolerance(a.maxHeightNm, a.wavelengthNm, a.tolerance));
    } catch (const std::invalid_argument& e) {  // includes TooManyTermsError
        throw UsageError(e.what());
    }
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"prism-diffraction: Stam diffraction reference (peaks of a grating, Taylor term bound)"};
    app.require_subcommand(1);
    PeaksArgs peaks;
    CLI::App* peaksCmd = app.add_subcommand("peaks", "diffraction peaks in the plane of incidence");
    peaksCmd->add_option("--height-field", peaks.heightField, "sinusoid, blazed, cd, snake or png")
        ->capture_default_str();
    peaksCmd->add_option("--period-nm", peaks.periodNm, "grating period d (also names the orders)")
        ->capture_default_str();
    peaksCmd->add_option("--amplitude-nm", peaks.amplitudeNm, "grating amplitude A")->capture_default_str();
    peaksCmd->add_option("--incidence-deg", peaks.incidenceDeg, "light angle T from the normal, 0..89.9")
        ->capture_default_str();
    peaksCmd->add_option("--wavelengths-nm", peaks.wavelengthsNm, "comma-separated wavelengths, 300..900 nm")
        ->delimiter(',')
        ->required();
    peaksCmd->add_option("--terms", peaks.terms, "Taylor terms N (default: from --tolerance)");
    peaksCmd->add_option("--tolerance", peaks.tolerance, "Taylor error bound when --terms is not given")
        ->capture_default_str();
    peaksCmd->add_flag("--exact", peaks.exact, "FFT of exp(i k w h) per sample, no Taylor series");
    peaksCmd->add_flag("--json", peaks.json, "print {\"peaks\":[...]}");
    peaksCmd->add_option("--periods", peaks.periods, "grating periods in the patch")->capture_default_str();
    peaksCmd->add_option("--samples-per-period", peaks.samplesPerPeriod)->capture_default_str();
    peaksCmd->add_option("--png", peaks.png, "height-field PNG (8 or 16 bit) for --height-field png");
    peaksCmd->add_option("--nm-per-pixel", peaks.nmPerPixel, "PNG pixel size");
    peaksCmd->add_option("--height-scale-nm", peaks.heightScaleNm, "height of the PNG's maximum value");
    BoundArgs bound;
    CLI::App* boundCmd = app.add_subcommand("bound", "Taylor terms N for a height, wavelength and tolerance");
    boundCmd->add_option("--max-height-nm", bound.maxHeightNm, "largest |h| after mean subtraction")->required();
    boundCmd->add_option("--wavelength-nm", bound.wavelengthNm, "shortest wavelength, 300..900 nm")->required();
    boundCmd->add_option("--tolerance", bound.tolerance, "bound on the series' error, in (0, 1)")->required();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    }
    try {
        if (peaksCmd->parsed()) refuseUnusedPeaksFlags(*peaksCmd, peaks);
        return peaksCmd->parsed() ? runPeaks(peaks) : runBound(bound);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "prism-diffraction: error: %s\n", e.what());
        return kExitBadInput;
    }
}
