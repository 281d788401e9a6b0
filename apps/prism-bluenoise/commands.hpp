// The subcommands of prism-bluenoise: their arguments, CLI11 registration and actions.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace prism::bluenoise::app {

// Bad arguments found after parsing (e.g. a malformed --size): exit status 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct GenerateArgs {
    std::string size;
    int depth = 1;
    double sigma = 1.5;
    std::uint64_t seed = 0;
    int bits = 8;
    std::string out;
    bool spatiotemporal = false;
    double sigmaTime = 1.9;
};

struct MeasureArgs {
    std::string file;
    bool json = false;
    std::string spectrumSvg;
};

struct RenderArgs {
    int spp = 1;
    std::string sampler = "bluenoise";
    int frame = 0;
    int frames = 1;
    std::string size = "128x128";
    int maskSize = 128;
    int stackDepth = 32;
    int block = 8;
    bool aPosteriori = false;
    bool noRetarget = false;
    std::string schedule = "exponential";
    int epochs = 32;
    std::string retargetCache;
    std::string scene = "classic";
    int reference = 0;
    std::string out;
    std::string liveRecord;  // also write the shader's inputs as JSON (live_record.hpp)
};

void addGenerate(CLI::App& app, GenerateArgs& args);
void addRender(CLI::App& app, RenderArgs& args);
// Throws UsageError for a flag the render would not use (e.g. --block without sorted).
void checkRenderFlags(const CLI::App& cmd, const RenderArgs& args);
int runRender(const RenderArgs& args);
void addMeasure(CLI::App& app, MeasureArgs& args);
int runGenerate(const GenerateArgs& args);
int runMeasure(const MeasureArgs& args);

// "WxH" with W, H in 1..512.
void parseSize(const std::string& text, int& width, int& height);

}  // namespace prism::bluenoise::app
