// `render`: the soft-shadow Monte Carlo demo with the white, blue-noise or sorted sampler
// (prism/bluenoise/soft_shadows.hpp), written as a grey PNG.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "commands.hpp"
#include "live_record.hpp"
#include "prism/bluenoise/gray_png.hpp"
#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"

namespace prism::bluenoise::app {

void addRender(CLI::App& app, RenderArgs& args) {
    CLI::App* cmd = app.add_subcommand("render", "render the soft-shadow demo scene with a sampler");
    cmd->add_option("--spp", args.spp, "samples per pixel per frame")->check(CLI::Range(1, 65536));
    cmd->add_option("--sampler", args.sampler, "white, bluenoise, sorted or stack (a spatiotemporal stack)")
        ->check(CLI::IsMember({"white", "bluenoise", "sorted", "stack"}));
    cmd->add_option("--stack-depth", args.stackDepth, "stack: slices of the spatiotemporal stack (mask-size square)")
        ->check(CLI::Range(1, 256));
    cmd->add_option("--frame", args.frame, "render frame K of the sequence")->check(CLI::Range(0, 2147483647));
    cmd->add_option("--frames", args.frames, "write the mean of frames 0..K-1")->check(CLI::Range(1, 100000));
    cmd->add_option("--size", args.size, "image WxH (each 1..512)");
    cmd->add_option("--mask-size", args.maskSize, "blue-noise mask side")->check(CLI::Range(1, 512));
    cmd->add_option("--block", args.block, "sorting block: 4, 8 or 16")->check(CLI::IsMember({4, 8, 16}));
    cmd->add_flag("--a-posteriori", args.aPosteriori,
                  "sorted: render, sort and render each frame again (static scene)");
    cmd->add_flag("--no-retarget", args.noRetarget, "sorted: skip the retargeting pass");
    cmd->add_option("--schedule", args.schedule, "annealing cooling: hajek, linear, exponential, inverse")
        ->check(CLI::IsMember({"hajek", "linear", "exponential", "inverse"}));
    cmd->add_option("--epochs", args.epochs, "annealing epochs (W*H moves each)")->check(CLI::Range(0, 100000));
    cmd->add_option("--retarget-cache", args.retargetCache, "file caching the retarget permutation");
    cmd->add_option("--scene", args.scene, "classic, black or white")
        ->check(CLI::IsMember({"classic", "black", "white"}));
    cmd->add_option("--reference", args.reference, "render the N-sample stratified reference instead")
        ->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--out", args.out, "PNG path (8-bit grey, clamped to [0, 1])")->required();
    cmd->add_option("--live-record", args.liveRecord,
                    "also write the GPU shader's inputs of this frame (JSON) for the report's live view (docs/web.md)");
    cmd->callback([cmd, &args] { checkRenderFlags(*cmd, args); });
}

// Every flag given is used by the render it asks for, or refused (exit 2): none is ignored.
void checkRenderFlags(const CLI::App& cmd, const RenderArgs& args) {
    auto given = [&cmd](const char* flag) { return cmd.count(flag) > 0; };
    const auto refuse = [](const std::string& flag, const std::string& why) { throw UsageError(flag + ": " + why); };
    if (args.reference > 0) {
        for (const char* f :
             {"--spp", "--sampler", "--stack-depth", "--frame", "--frames", "--mask-size", "--block", "--a-posteriori",
              "--no-retarget", "--schedule", "--epochs", "--retarget-cache", "--live-record"})
            if (given(f)) refuse(f, "--reference renders the stratified reference, which uses no sampler settings");
        return;
    }
    if (given("--stack-depth") && args.sampler != "stack") refuse("--stack-depth", "only for --sampler stack");
    if (given("--mask-size") && args.sampler == "white") refuse("--mask-size", "the white sampler uses no mask");
    for (const char* f : {"--block", "--a-posteriori", "--no-retarget", "--schedule", "--epochs", "--retarget-cache"})
        if (given(f) && args.sampler != "sorted") refuse(f, "only for --sampler sorted");
    const bool retargets = (args.frames > 1 || args.frame > 0) && !args.noRetarget && !args.aPosteriori;
    for (const char* f : {"--schedule", "--epochs", "--retarget-cache"})
        if (given(f) && args.sampler == "sorted" && !retargets)
            refuse(f, "this render does not retarget (frame 0 alone, --no-retarget or --a-posteriori)");
    if (args.noRetarget && args.aPosteriori) refuse("--no-retarget", "--a-posteriori never retargets");
    if (given("--live-record") && (args.frames > 1 || (args.sampler != "white" && args.sampler != "bluenoise")))
        refuse("--live-record", "the live view draws one frame of the white or bluenoise sampler (docs/web.md)");
    if (given("--frame") && given("--frames"))
        refuse("--frame", "--frames K renders the mean of frames 0..K-1; give one of them");
}

int runRender(const RenderArgs& args) {
    RenderOptions options;
    parseSize(args.size, options.width, options.height);
    const SoftShadowScene scene = args.scene == "black"   ? SoftShadowScene::black()
                                  : args.scene == "white" ? SoftShadowScene::white()
                                                          : SoftShadowScene::classic();
    RealImage image;
    const auto start = std::chrono::steady_clock::now();
    if (args.reference > 0) {
        image = renderReference(scene, options.width, options.height, args.reference).image;
    } else {
        options.spp = args.spp;
        options.frame = args.frame;
        options.frames = args.frames;
        options.block = args.block;
        options.aPosteriori = args.aPosteriori;
        options.sampler = args.sampler == "stack"       ? SamplerKind::Stack
                          : args.sampler == "sorted"    ? SamplerKind::Sorted
                          : args.sampler == "bluenoise" ? SamplerKind::BlueNoise
                                                        : SamplerKind::White;
        if (options.sampler == SamplerKind::Sorted && args.frame > 100000)
            throw UsageError("--frame " + std::to_string(args.frame) +
                             ": the sorted sampler replays every frame before K; use K <= 100000");
        VoidAndClusterOptions maskOptions;
        maskOptions.width = maskOptions.height = args.maskSize;
        StochasticSetup setup = StochasticSetup::make(generateVoidAndCluster(maskOptions));
        if (options.sampler == SamplerKind::Stack)
            setup.tables.setStack(generateSpatiotemporal(maskOptions, args.stackDepth));
        // Frame 0 alone never retargets; otherwise build (or read) the permutation.
        const bool needsRetarget = args.frames > 1 || args.frame > 0;
        if (options.sampler == SamplerKind::Sorted && needsRetarget && !args.noRetarget && !args.aPosteriori &&
            setup.mask.size() > 1) {
            RetargetOptions r;
            r.shiftX = setup.shiftX;
            r.shiftY = setup.shiftY;
            r.schedule = parseCoolingSchedule(args.schedule);
            r.epochs = args.epochs;
            setup.retarget = args.retargetCache.empty() ? computeRetarget(setup.mask, r).permutation
                                                        : loadOrComputeRetarget(setup.mask, r, args.retargetCache);
        }
        image = renderSoftShadows(scene, setup, options);
        if (!args.liveRecord.empty()) writeLiveRecord(args.liveRecord, args.out, scene, setup, options);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    GrayImage png{image.width, image.height, 8, {}};
    for (double v : image.values)
        png.values.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)));
    writeGrayPng(args.out, png);
    std::cerr << "prism-bluenoise: wrote " << args.out << " in " << seconds << " s\n";
    return 0;
}

}  // namespace prism::bluenoise::app
