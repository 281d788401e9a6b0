// The viewer's CLI11 command line (viewer_options.hpp).
#include "viewer_options.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

namespace prism::viewer {

std::optional<ViewerOptions> parseViewerOptions(int argc, char** argv, int& exitCode) {
    ViewerOptions o;
    CLI::App app{
        "viewer: an interactive window over the Prism catalogue and scenes, with panels for every "
        "system (run under xvfb-run -a on a headless machine)",
        "viewer"};
    app.set_version_flag("--version", std::string("viewer (Prism) ") + PRISM_VERSION);
    app.add_option("--scene", o.scene, "open a scene JSON file (docs/scenes.md) instead of the catalogue view")
        ->check(CLI::ExistingFile);
    app.add_option("--shader", o.shader, "catalogue shader of the catalogue view")->capture_default_str();
    app.add_option("--variant", o.variant, "variant axis value AXIS=VALUE (repeatable), e.g. BLINN=1");
    app.add_option("--mesh", o.mesh, "built-in mesh (sphere, icosphere, torus, cube, trefoil)")->capture_default_str();
    app.add_option("--subdivision", o.subdivision, "mesh subdivision level")
        ->check(CLI::Range(0u, 6u))
        ->capture_default_str();
    app.add_option("--frames", o.frames, "quit after N frames (0: run until the window closes)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--screenshot", o.screenshot, "write the last frame to this PNG and exit");
    app.add_option("--script", o.script, "play key and parameter events from FILE, one line per frame (docs/viewer.md)")
        ->check(CLI::ExistingFile);
    auto* watch = app.add_flag("--watch", o.watch, "hot reload: rebuild edited shaders and modules in process");
    app.add_option("--source-root", o.sourceRoot,
                   "a copy of the tree the catalogue was built from, for --watch to watch instead (default: that "
                   "tree, as prism_add_shaders recorded it)")
        ->needs(watch);  // used only by --watch: alone it would be accepted and ignored
    app.add_flag("!--no-panels", o.panels, "hide the ImGui panels");
    app.add_option("--width", o.width, "window width")->check(CLI::Range(64, 8192));
    app.add_option("--height", o.height, "window height")->check(CLI::Range(64, 8192));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            app.exit(e);  // --help / --version print to stdout
            exitCode = 0;
        } else {
            std::cerr << "viewer: error: " << e.what() << "\n"
                      << "run 'viewer --help' for the options\n";
            exitCode = 2;
        }
        return std::nullopt;
    }
    for (const auto& v : o.variant)
        if (v.find('=') == std::string::npos || v.front() == '=') {
            std::cerr << "viewer: error: --variant wants AXIS=VALUE, got '" << v << "'\n";
            exitCode = 2;
            return std::nullopt;
        }
    return o;
}

}  // namespace prism::viewer
