// prism_bench_bluenoise --out DIR: the sampler trade (error vs cost, Pareto front), mask
// size vs quality and annealing effort vs energy; tables on stdout, CSV and SVG in DIR.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/metrics.hpp"
#include "prism/bluenoise/retarget.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/spectrum_svg.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
#ifdef PRISM_BENCH_BLUENOISE_GL
#include "prism/bluenoise/gl_soft_shadows.hpp"
#include "prism/gl/gl_context.hpp"
#endif

namespace bn = prism::bluenoise;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

const char* samplerName(bn::SamplerKind k) {
    return k == bn::SamplerKind::White ? "white" : k == bn::SamplerKind::BlueNoise ? "bluenoise" : "sorted";
}

struct Point {
    bn::SamplerKind sampler;
    int spp, frames;
    double msPerFrame, rms, blurred;
};

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"prism_bench_bluenoise: blue-noise sampling trade-offs (docs/bluenoise.md)"};
    std::string out = "bluenoise-bench";
    int size = 128, repeats = 3, maxMask = 256;
    app.add_option("--out", out, "directory for the CSV and SVG files");
    app.add_option("--size", size, "image side in pixels")->check(CLI::Range(16, 512));
    app.add_option("--repeats", repeats, "timing repeats (median)")->check(CLI::Range(1, 20));
    app.add_option("--max-mask", maxMask, "largest mask side in the mask-size sweep")->check(CLI::Range(16, 512));
    bool gpu = false;
    app.add_flag("--gl", gpu, "also time the GPU version (llvmpipe) per sampler and spp");
    CLI11_PARSE(app, argc, argv);
    std::filesystem::create_directories(out);

    // --- 1. sampler x spp x frames -------------------------------------------------
    const bn::SoftShadowScene scene = bn::SoftShadowScene::classic();
    const bn::Reference reference = bn::renderReference(scene, size, size, 1024);
    bn::StochasticSetup setup = bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 128, .height = 128}));
    {
        bn::RetargetOptions r;
        r.shiftX = setup.shiftX;
        r.shiftY = setup.shiftY;
        setup.retarget = bn::computeRetarget(setup.mask, r).permutation;
    }
    std::vector<Point> points;
    std::printf("## Sampler x spp x frames (soft shadows %dx%d, penumbra pixels vs 1024-spp reference)\n", size, size);
    std::printf("%-10s %4s %6s %12s %10s %12s\n", "sampler", "spp", "frames", "ms/frame", "rms", "blurred_rms");
    std::ostringstream csv;
    csv << "sampler,spp,frames,ms_per_frame,rms,blurred_rms\n";
    for (bn::SamplerKind kind : {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted})
        for (int spp : {1, 2, 4, 8, 16})
            for (int frames : {1, 4, 16, 32}) {
                bn::RenderOptions o;
                o.width = o.height = size;
                o.sampler = kind;
                o.spp = spp;
                o.frames = frames;
                std::vector<double> times;
                bn::RealImage image;
                for (int k = 0; k < repeats; ++k) {
                    const auto start = Clock::now();
                    image = bn::renderSoftShadows(scene, setup, o);
                    times.push_back(secondsSince(start) * 1000.0 / frames);
                }
                const bn::ErrorStats e = bn::compareToReference(image, reference);
                points.push_back({kind, spp, frames, median(times), e.rms, e.blurredRms});
                std::printf("%-10s %4d %6d %12.2f %10.5f %12.5f\n", samplerName(kind), spp, frames, median(times),
                            e.rms, e.blurredRms);
                csv << samplerName(kind) << "," << spp << "," << frames << "," << median(times) << "," << e.rms << ","
                    << e.blurredRms << "\n";
            }
    bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_tradeoff.csv", csv.str());

    std::printf("\n## Pareto front per frames accumulated (ms/frame vs blurred RMS; lower is better in both)\n");
    for (int frames : {1, 4, 16, 32}) {
        std::printf("frames %2d:", frames);
        for (const Point& p : points) {
            if (p.frames != frames) continue;
            bool dominated = false;
            for (const Point& q : points)
                if (q.frames == frames && &q != &p && q.msPerFrame <= p.msPerFrame && q.blurred <= p.blurred &&
                    (q.msPerFrame < p.msPerFrame || q.blurred < p.blurred))
                    dominated = true;
            if (!dominated)
                std::printf("  %s@%dspp (%.2f ms, %.5f)", samplerName(p.sampler), p.spp, p.msPerFrame, p.blurred);
        }
        std::printf("\n");
    }
    auto find = [&](bn::SamplerKind k, int spp, int frames) {
        for (const Point& p : points)
            if (p.sampler == k && p.spp == spp && p.frames == frames) return p;
        return points.front();
    };
    for (int frames : {1, 32}) {
        const Point b1 = find(bn::SamplerKind::BlueNoise, 1, frames), w2 = find(bn::SamplerKind::White, 2, frames),
                    w4 = find(bn::SamplerKind::White, 4, frames);
        std::printf(
            "frames %2d: 1 spp bluenoise blurred %.5f at %.2f ms vs 2 spp white %.5f at %.2f ms, 4 spp white %.5f at "
            "%.2f ms\n",
            frames, b1.blurred, b1.msPerFrame, w2.blurred, w2.msPerFrame, w4.blurred, w4.msPerFrame);
    }
    std::printf(
        "targets (issue 13): 1 frame blurred bluenoise/white <= 0.5: %.3f; 32 frames rms <= 0.35: %.3f, blurred <= "
        "0.25: %.3f\n",
        find(bn::SamplerKind::BlueNoise, 1, 1).blurred / find(bn::SamplerKind::White, 1, 1).blurred,
        find(bn::SamplerKind::BlueNoise, 1, 32).rms / find(bn::SamplerKind::White, 1, 32).rms,
        find(bn::SamplerKind::BlueNoise, 1, 32).blurred / find(bn::SamplerKind::White, 1, 32).blurred);

    // The acceptance ratios of issue 13, on the classic scene and with a wider light.
    std::printf(
        "\n## Acceptance ratios (1 spp; blurred = Gaussian sigma 1 px; lf = low-frequency power ratio of the error)\n");
    for (double halfWidth : {0.01, 0.05}) {
        bn::SoftShadowScene variant = scene;
        variant.lightHalfWidth = halfWidth;
        const bn::Reference ref =
            halfWidth == scene.lightHalfWidth ? reference : bn::renderReference(variant, size, size, 1024);
        auto error = [&](bn::SamplerKind kind, int frames, int frame, bool aPosteriori, int block) {
            bn::RenderOptions o;
            o.width = o.height = size;
            o.sampler = kind;
            o.frames = frames;
            o.frame = frame;
            o.aPosteriori = aPosteriori;
            o.block = block;
            return bn::compareToReference(bn::renderSoftShadows(variant, setup, o), ref);
        };
        const bn::ErrorStats w1 = error(bn::SamplerKind::White, 1, 0, false, 8),
                             b1 = error(bn::SamplerKind::BlueNoise, 1, 0, false, 8);
        const bn::ErrorStats w32 = error(bn::SamplerKind::White, 32, 0, false, 8),
                             b32 = error(bn::SamplerKind::BlueNoise, 32, 0, false, 8);
        const bn::ErrorStats s8 = error(bn::SamplerKind::Sorted, 1, 0, true, 8),
                             s4 = error(bn::SamplerKind::Sorted, 1, 0, true, 4);
        const bn::ErrorStats m = error(bn::SamplerKind::BlueNoise, 1, 1000000, false, 8);
        std::printf("light half-width %.2f (%d penumbra px):\n", halfWidth, w1.pixels);
        std::printf(
            "  1 frame  blurred blue/white %.5f/%.5f = %.3f (target <= 0.5); lf %.4f/%.4f = %.3f (target <= 0.3)\n",
            b1.blurredRms, w1.blurredRms, b1.blurredRms / w1.blurredRms, b1.lowFrequencyRatio, w1.lowFrequencyRatio,
            b1.lowFrequencyRatio / w1.lowFrequencyRatio);
        std::printf(
            "  32 frames rms blue/white %.5f/%.5f = %.3f (target <= 0.35); blurred %.5f/%.5f = %.3f (target <= 0.25)\n",
            b32.rms, w32.rms, b32.rms / w32.rms, b32.blurredRms, w32.blurredRms, b32.blurredRms / w32.blurredRms);
        std::printf("  sorting alone: white/sorted blurred 8x8 %.5f/%.5f = %.3fx (target >= 1.4), 4x4 %.5f = %.3fx\n",
                    w1.blurredRms, s8.blurredRms, w1.blurredRms / s8.blurredRms, s4.blurredRms,
                    w1.blurredRms / s4.blurredRms);
        std::printf("  frame 10^6 blue blurred %.5f (frame 0: %.5f)\n", m.blurredRms, b1.blurredRms);
    }
    {
        // The spatiotemporal stack sampler (64x64x32 tiles) against golden-ratio offsets of a
        // 64x64 mask, on the classic scene.
        bn::StochasticSetup stackSetup =
            bn::StochasticSetup::make(bn::generateVoidAndCluster({.width = 64, .height = 64}));
        const auto start = Clock::now();
        stackSetup.tables.setStack(bn::generateSpatiotemporal({.width = 64, .height = 64}, 32));
        const double seconds = secondsSince(start);
        auto error = [&](bn::SamplerKind kind, int frames) {
            bn::RenderOptions o;
            o.width = o.height = size;
            o.sampler = kind;
            o.frames = frames;
            return bn::compareToReference(bn::renderSoftShadows(scene, stackSetup, o), reference);
        };
        const bn::ErrorStats s1 = error(bn::SamplerKind::Stack, 1), g1 = error(bn::SamplerKind::BlueNoise, 1);
        const bn::ErrorStats s32 = error(bn::SamplerKind::Stack, 32), g32 = error(bn::SamplerKind::BlueNoise, 32);
        std::printf("stack sampler (64x64x32, generated in %.2f s) vs golden-ratio offsets of a 64x64 mask:\n",
                    seconds);
        std::printf("  1 frame blurred %.5f vs %.5f; 32 frames rms %.5f vs %.5f, blurred %.5f vs %.5f\n", s1.blurredRms,
                    g1.blurredRms, s32.rms, g32.rms, s32.blurredRms, g32.blurredRms);
    }

#ifdef PRISM_BENCH_BLUENOISE_GL
    if (gpu) {
        auto context = prism::gl::createContext();
        bn::GlSoftShadows renderer(size, size);
        std::printf(
            "\n## GPU (%s): ms per frame over 32 frames incl. readback and, for sorted, the CPU sorting and "
            "retargeting passes\n",
            context->info().renderer.c_str());
        std::printf("%-10s %4s %12s %12s\n", "sampler", "spp", "ms/frame", "blurred_rms");
        std::ostringstream gl;
        gl << "sampler,spp,frames,ms_per_frame,blurred_rms\n";
        for (bn::SamplerKind kind : {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted})
            for (int spp : {1, 2, 4, 8, 16}) {
                bn::RenderOptions o;
                o.width = o.height = size;
                o.sampler = kind;
                o.spp = spp;
                o.frames = 32;
                std::vector<double> times;
                bn::RealImage image;
                for (int k = 0; k < repeats; ++k) {
                    const auto start = Clock::now();
                    image = renderer.render(scene, setup, o);
                    times.push_back(secondsSince(start) * 1000.0 / o.frames);
                }
                const bn::ErrorStats e = bn::compareToReference(image, reference);
                std::printf("%-10s %4d %12.2f %12.5f\n", samplerName(kind), spp, median(times), e.blurredRms);
                gl << samplerName(kind) << "," << spp << ",32," << median(times) << "," << e.blurredRms << "\n";
            }
        bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_gpu.csv", gl.str());
    }
#else
    if (gpu) std::printf("\n(--gl: this build has no prism_bluenoise GL library)\n");
#endif

    // Convergence over frames at 1 spp (every frame count 1..32).
    std::vector<bn::PlotSeries> convergence;
    std::ostringstream conv;
    conv << "sampler,frames,rms,blurred_rms\n";
    for (bn::SamplerKind kind : {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted}) {
        bn::PlotSeries perPixel{std::string(samplerName(kind)) + " rms", {}},
            blurred{std::string(samplerName(kind)) + " blurred", {}};
        for (int frames : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32}) {
            bn::RenderOptions o;
            o.width = o.height = size;
            o.sampler = kind;
            o.frames = frames;
            const bn::ErrorStats e = bn::compareToReference(bn::renderSoftShadows(scene, setup, o), reference);
            perPixel.points.emplace_back(frames, e.rms);
            blurred.points.emplace_back(frames, e.blurredRms);
            conv << samplerName(kind) << "," << frames << "," << e.rms << "," << e.blurredRms << "\n";
        }
        convergence.push_back(perPixel);
        convergence.push_back(blurred);
    }
    bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_convergence.csv", conv.str());
    bn::writeFileAtomically(
        std::filesystem::path(out) / "bluenoise_convergence.svg",
        bn::linePlotSvg("frames accumulated (1 spp each)", "RMS error (penumbra pixels)", convergence, true));

    // --- 2. mask size vs quality ---------------------------------------------------
    std::printf("\n## Mask size vs quality (sigma 1.5, seed 0; render: 1 spp bluenoise, 1 frame)\n");
    std::printf("%-8s %10s %10s %10s %10s %12s\n", "mask", "gen_s", "lf_ratio", "fast", "aniso_dB", "blurred_rms");
    std::ostringstream masks;
    masks << "side,generate_s,low_frequency_power_ratio,filtered_error_sigma1,anisotropy_db,render_blurred_rms\n";
    std::vector<bn::NamedSpectrum> spectra;
    for (int side = 16; side <= maxMask; side *= 2) {
        std::vector<double> times;
        bn::Mask mask;
        for (int k = 0; k < (side >= 256 ? 1 : repeats); ++k) {
            const auto start = Clock::now();
            mask = bn::generateVoidAndCluster({.width = side, .height = side});
            times.push_back(secondsSince(start));
        }
        const bn::GrayImage gray{side, side, 8, bn::quantize(mask, 8)};
        const bn::MaskMetrics m = bn::measureMask(gray);
        bn::StochasticSetup s = bn::StochasticSetup::make(mask);
        bn::RenderOptions o;
        o.width = o.height = size;
        o.sampler = bn::SamplerKind::BlueNoise;
        const bn::ErrorStats e = bn::compareToReference(bn::renderSoftShadows(scene, s, o), reference);
        std::printf("%4dx%-4d %10.3f %10.5f %10.5f %10.3f %12.5f\n", side, side, median(times),
                    m.lowFrequencyPowerRatio, m.filteredErrorSigma1, m.anisotropyDb, e.blurredRms);
        masks << side << "," << median(times) << "," << m.lowFrequencyPowerRatio << "," << m.filteredErrorSigma1 << ","
              << m.anisotropyDb << "," << e.blurredRms << "\n";
        if (side == 128) {
            spectra.push_back({"void-and-cluster 128x128", bn::radialPowerSpectrum(gray)});
            bn::writeGrayPng(std::filesystem::path(out) / "mask_128.png", gray);
        }
    }
    const bn::GrayImage white = bn::whiteNoiseImage(128, 128, 8, 1);
    spectra.push_back({"white noise 128x128", bn::radialPowerSpectrum(white)});
    bn::writeGrayPng(std::filesystem::path(out) / "white_128.png", white);
    {
        const bn::MaskMetrics w = bn::measureMask(white);
        std::printf("white 128 %10s %10.5f %10.5f %10.3f\n", "-", w.lowFrequencyPowerRatio, w.filteredErrorSigma1,
                    w.anisotropyDb);
        masks << "white128,0," << w.lowFrequencyPowerRatio << "," << w.filteredErrorSigma1 << "," << w.anisotropyDb
              << ",\n";
    }
    std::printf("targets (issue 13, 128^2): lf_ratio <= 0.01, fast <= 0.046 (white ~0.114), 128^2 in <= 1 s\n");
    bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_masks.csv", masks.str());
    bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_spectra.svg", bn::spectrumSvg(spectra));

    // --- 2b. mask stacks: golden-ratio slices vs spatiotemporal void-and-cluster ------
    {
        std::printf("\n## Mask stacks 64x64x16: every slice's quality, and each pixel's values over the slices\n");
        std::printf("%-24s %8s %10s %10s %10s %8s %8s %8s\n", "stack", "gen_s", "fast_mean", "fast_worst", "lf_worst",
                    "gap4", "gap8", "gap16");
        std::ostringstream stacks;
        stacks << "stack,generate_s,fast_mean,fast_worst,lf_worst,gap4,gap8,gap16\n";
        auto report = [&](const std::string& name, double seconds,
                          const std::vector<std::vector<std::uint32_t>>& slices) {
            double fastMean = 0.0, fastWorst = 0.0, lfWorst = 0.0;
            for (const auto& slice : slices) {
                bn::GrayImage g{64, 64, 8, {}};
                for (std::uint32_t v : slice) g.values.push_back(static_cast<std::uint16_t>(v >> 24));
                const double f = bn::filteredErrorSigma1(g);
                fastMean += f / static_cast<double>(slices.size());
                fastWorst = std::max(fastWorst, f);
                lfWorst = std::max(lfWorst, bn::lowFrequencyPowerRatio(g));
            }
            double gaps[3] = {0, 0, 0};
            const std::size_t ks[3] = {4, 8, 16};
            for (std::size_t i = 0; i < slices[0].size(); ++i)
                for (int j = 0; j < 3; ++j) {
                    std::vector<double> v;
                    for (std::size_t t = 0; t < ks[j]; ++t) v.push_back(slices[t][i] / 4294967296.0);
                    std::sort(v.begin(), v.end());
                    double gap = 1.0 - v.back() + v.front();
                    for (std::size_t k = 1; k < v.size(); ++k) gap = std::max(gap, v[k] - v[k - 1]);
                    gaps[j] += gap / static_cast<double>(slices[0].size());
                }
            std::printf("%-24s %8.2f %10.4f %10.4f %10.5f %8.3f %8.3f %8.3f\n", name.c_str(), seconds, fastMean,
                        fastWorst, lfWorst, gaps[0], gaps[1], gaps[2]);
            stacks << name << "," << seconds << "," << fastMean << "," << fastWorst << "," << lfWorst << "," << gaps[0]
                   << "," << gaps[1] << "," << gaps[2] << "\n";
        };
        {
            const auto start = Clock::now();
            const bn::Mask m = bn::generateVoidAndCluster({.width = 64, .height = 64});
            std::vector<std::vector<std::uint32_t>> slices;
            for (std::uint32_t t = 0; t < 16; ++t) slices.push_back(bn::goldenRatioSlice(m, t));
            report("golden-ratio slices", secondsSince(start), slices);
        }
        for (double sigmaTime : {1.0, 1.9, 3.0}) {
            const auto start = Clock::now();
            const std::vector<bn::Mask> stack = bn::generateSpatiotemporal({.width = 64, .height = 64}, 16, sigmaTime);
            const double seconds = secondsSince(start);
            std::vector<std::vector<std::uint32_t>> slices;
            for (const bn::Mask& m : stack) slices.push_back(bn::fixedPoint32(m));
            char name[48];
            std::snprintf(name, sizeof name, "spatiotemporal st=%.1f", sigmaTime);
            report(name, seconds, slices);
        }
        {
            std::vector<std::vector<std::uint32_t>> slices;
            for (std::uint64_t seed = 100; seed < 116; ++seed) {
                bn::VoidAndClusterOptions o{.width = 64, .height = 64};
                o.seed = seed;
                slices.push_back(bn::fixedPoint32(bn::generateVoidAndCluster(o)));
            }
            report("16 independent masks", 0.0, slices);
        }
        bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_stacks.csv", stacks.str());
    }

    // --- 3. annealing effort vs energy vs time ------------------------------------
    std::printf(
        "\n## Retarget annealing on a 64x64 mask (radius 6, sigma_i 2.1, sigma_s 1): epochs vs energy vs time\n");
    std::printf("%-12s %6s %10s %12s %12s %12s %10s\n", "schedule", "epochs", "seconds", "energy0", "energy", "target0",
                "target");
    std::ostringstream anneal;
    anneal << "schedule,epochs,seconds,initial_energy,final_energy,initial_target,final_target,accepted,moves\n";
    const bn::Mask mask64 = bn::generateVoidAndCluster({.width = 64, .height = 64});
    for (auto schedule : {bn::CoolingSchedule::Hajek, bn::CoolingSchedule::Linear, bn::CoolingSchedule::Exponential,
                          bn::CoolingSchedule::Inverse})
        for (int epochs : {0, 4, 16, 64}) {
            bn::RetargetOptions r;
            bn::frameShift(64, 64, r.shiftX, r.shiftY);
            r.schedule = schedule;
            r.epochs = epochs;
            const auto start = Clock::now();
            const bn::RetargetResult res = bn::computeRetarget(mask64, r);
            const double seconds = secondsSince(start);
            std::printf("%-12s %6d %10.3f %12.1f %12.1f %12.1f %10.1f\n", bn::coolingScheduleName(schedule), epochs,
                        seconds, res.initialEnergy, res.finalEnergy, res.initialTarget, res.finalTarget);
            anneal << bn::coolingScheduleName(schedule) << "," << epochs << "," << seconds << "," << res.initialEnergy
                   << "," << res.finalEnergy << "," << res.initialTarget << "," << res.finalTarget << ","
                   << res.accepted << "," << res.moves << "\n";
        }
    bn::writeFileAtomically(std::filesystem::path(out) / "bluenoise_annealing.csv", anneal.str());
    std::printf(
        "\nwrote %s/{bluenoise_tradeoff,bluenoise_convergence,bluenoise_masks,bluenoise_annealing}.csv, "
        "bluenoise_convergence.svg, bluenoise_spectra.svg, mask_128.png, white_128.png\n",
        out.c_str());
    return 0;
}
