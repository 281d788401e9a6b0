// The one list of output generators (output_generator.hpp): adding an output registers it here.
#include "output_generator.hpp"

namespace prism::shaderc {

// Each defined in its generator_*.cpp.
std::unique_ptr<OutputGenerator> makeHeaderGenerator();
std::unique_ptr<OutputGenerator> makeSpirvFilesGenerator();
std::unique_ptr<OutputGenerator> makeWebCatalogueGenerator();
std::unique_ptr<OutputGenerator> makeReflectionJsonGenerator();
std::unique_ptr<OutputGenerator> makeGlslTextsGenerator();

const std::vector<std::unique_ptr<OutputGenerator>>& outputGenerators() {
    static const std::vector<std::unique_ptr<OutputGenerator>> generators = [] {
        std::vector<std::unique_ptr<OutputGenerator>> list;
        for (auto make : {makeHeaderGenerator, makeSpirvFilesGenerator, makeWebCatalogueGenerator,
                          makeReflectionJsonGenerator, makeGlslTextsGenerator})
            list.push_back(make());
        return list;
    }();
    return generators;
}

std::vector<std::string> outputPathsNamed(const Options& options) {
    std::vector<std::string> paths;
    for (const auto& g : outputGenerators())
        for (std::string& p : g->pathsNamed(options)) paths.push_back(std::move(p));
    return paths;
}

}  // namespace prism::shaderc
