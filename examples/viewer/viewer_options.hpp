// The viewer's command line (CLI11): what to show first, how long to run, where to write
// the last frame, and the hot-reload and script hooks. --help and --version print and
// return exit code 0 before any window exists; a usage error returns 2.
//
//     int exitCode = 0;
//     std::optional<ViewerOptions> options = parseViewerOptions(argc, argv, exitCode);
//     if (!options) return exitCode;
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace prism::viewer {

struct ViewerOptions {
    std::string scene;  // --scene FILE.json: open a scene instead of the catalogue view
    std::string shader = "phong";
    std::vector<std::string> variant;  // --variant AXIS=VALUE (repeatable)
    std::string mesh = "sphere";
    unsigned subdivision = 3;
    long frames = 0;         // 0: until the window closes
    std::string screenshot;  // PNG of the last frame
    std::string script;      // --script FILE of key and parameter events, one per frame
    bool watch = false;
    std::string sourceRoot;  // --source-root: a copy of the catalogue's recorded tree; "": that tree
    bool panels = true;      // --no-panels hides the ImGui panels
    int width = 1100;
    int height = 760;
};

// nullopt with `exitCode` set: exit now (0 after --help/--version, 2 on a usage error).
std::optional<ViewerOptions> parseViewerOptions(int argc, char** argv, int& exitCode);

}  // namespace prism::viewer
