// `generate` and `measure`: masks to PNG files, PNG files to metrics.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/spectrum_svg.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace prism::bluenoise::app {

void addGenerate(CLI::App& app, GenerateArgs& args) {
    CLI::App* cmd = app.add_subcommand("generate", "write a void-and-cluster mask (or a stack of D slices) as PNG");
    cmd->add_option("--size", args.size, "WxH, each 1..512")->required();
    cmd->add_option("--depth", args.depth, "slices; >1 writes PATH/slice_000.png ..")->check(CLI::Range(1, 1000));
    cmd->add_option("--sigma", args.sigma, "Gaussian energy sigma in pixels")->check(CLI::Range(0.05, 64.0));
    cmd->add_option("--seed", args.seed, "RNG seed (same seed, same mask)");
    cmd->add_option("--bits", args.bits, "8 or 16 bits per pixel")->check(CLI::IsMember({8, 16}));
    cmd->add_option("--out", args.out, "PNG path (D = 1) or directory (D > 1)")->required();
    cmd->add_flag("--spatiotemporal", args.spatiotemporal,
                  "D > 1: a spatiotemporal void-and-cluster stack instead of golden-ratio slices of one mask");
    cmd->add_option("--sigma-time", args.sigmaTime, "spatiotemporal: Gaussian sigma across slices")
        ->check(CLI::Range(0.05, 64.0));
    cmd->callback([cmd, &args] {  // a flag is used or refused, never ignored
        if (cmd->count("--sigma-time") > 0 && !args.spatiotemporal)
            throw UsageError("--sigma-time needs --spatiotemporal");
    });
}

void addMeasure(CLI::App& app, MeasureArgs& args) {
    CLI::App* cmd = app.add_subcommand("measure", "print a mask's histogram, spectrum and FAST metrics");
    cmd->add_option("file", args.file, "grey PNG (8 or 16 bit)")->required();
    cmd->add_flag("--json", args.json, "print one JSON object");
    cmd->add_option("--spectrum-svg", args.spectrumSvg, "write the radially averaged power spectrum as SVG");
}

void parseSize(const std::string& text, int& width, int& height) {
    char x = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x' || width < 1 || height < 1 ||
        width > kMaxMaskSide || height > kMaxMaskSide)
        throw UsageError("--size '" + text + "' must be WxH with W and H in 1.." + std::to_string(kMaxMaskSide) +
                         ", e.g. --size 128x128");
}

int runGenerate(const GenerateArgs& args) {
    VoidAndClusterOptions options;
    parseSize(args.size, options.width, options.height);
    options.sigma = args.sigma;
    options.seed = args.seed;
    if (args.spatiotemporal && args.depth > kMaxMaskDepth)
        throw UsageError("--spatiotemporal supports --depth up to " + std::to_string(kMaxMaskDepth));
    const std::vector<Mask> stack = args.spatiotemporal ? generateSpatiotemporal(options, args.depth, args.sigmaTime)
                                                        : std::vector<Mask>{generateVoidAndCluster(options)};
    const Mask& mask = stack.front();
    const int shift = 32 - args.bits;
    for (int slice = 0; slice < args.depth; ++slice) {
        const std::vector<std::uint32_t> values = args.spatiotemporal
                                                      ? fixedPoint32(stack[static_cast<std::size_t>(slice)])
                                                      : goldenRatioSlice(mask, static_cast<std::uint32_t>(slice));
        GrayImage image{mask.width, mask.height, args.bits, {}};
        image.values.reserve(values.size());
        for (std::uint32_t v : values) image.values.push_back(static_cast<std::uint16_t>(v >> shift));
        std::filesystem::path path = args.out;
        if (args.depth > 1) {
            char name[32];
            std::snprintf(name, sizeof name, "slice_%03d.png", slice);
            path /= name;
        }
        writeGrayPng(path, image);
    }
    return 0;
}

int runMeasure(const MeasureArgs& args) {
    const GrayImage image = readGrayPng(args.file);
    const MaskMetrics m = measureMask(image);
    std::ostringstream out;
    out.precision(6);
    if (args.json) {
        out << "{\"file\": \"" << args.file << "\", \"width\": " << image.width << ", \"height\": " << image.height
            << ", \"bits\": " << image.bits << ", \"histogram_uniform\": " << (m.histogramUniform ? "true" : "false")
            << ", \"low_frequency_power_ratio\": " << m.lowFrequencyPowerRatio
            << ", \"filtered_error_sigma1\": " << m.filteredErrorSigma1 << ", \"anisotropy\": " << m.anisotropyDb
            << "}\n";
    } else {
        out << "file: " << args.file << " (" << image.width << "x" << image.height << ", " << image.bits << " bit)\n"
            << "histogram_uniform: " << (m.histogramUniform ? "true" : "false") << "\n"
            << "low_frequency_power_ratio: " << m.lowFrequencyPowerRatio << "\n"
            << "filtered_error_sigma1: " << m.filteredErrorSigma1 << "\n"
            << "anisotropy: " << m.anisotropyDb << " dB\n";
    }
    if (!args.spectrumSvg.empty())
        writeFileAtomically(
            args.spectrumSvg,
            spectrumSvg({{std::filesystem::path(args.file).filename().string(), radialPowerSpectrum(image)}}));
    std::cout << out.str();
    return 0;
}

}  // namespace prism::bluenoise::app
