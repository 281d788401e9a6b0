// prism-bluenoise: generate void-and-cluster blue-noise masks and measure dither masks
// and render the soft-shadow Monte Carlo demo (docs/bluenoise.md). Usage errors exit 2,
// other failures 1.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"prism-bluenoise: blue-noise dither masks and their metrics (docs/bluenoise.md)"};
    app.require_subcommand(1);
    prism::bluenoise::app::GenerateArgs generate;
    prism::bluenoise::app::MeasureArgs measure;
    prism::bluenoise::app::RenderArgs render;
    prism::bluenoise::app::addGenerate(app, generate);
    prism::bluenoise::app::addMeasure(app, measure);
    prism::bluenoise::app::addRender(app, render);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    } catch (const prism::bluenoise::app::UsageError& e) {
        std::cerr << "prism-bluenoise: error: " << e.what() << "\n";
        return 2;
    }
    try {
        if (app.got_subcommand("generate")) return prism::bluenoise::app::runGenerate(generate);
        if (app.got_subcommand("measure")) return prism::bluenoise::app::runMeasure(measure);
        if (app.got_subcommand("render")) return prism::bluenoise::app::runRender(render);
    } catch (const prism::bluenoise::app::UsageError& e) {
        std::cerr << "prism-bluenoise: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    return 2;
}
