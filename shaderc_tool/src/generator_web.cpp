// The output generator of --emit-web FILE.js (output_generator.hpp): the web catalogue (web_writer.hpp).
#include <filesystem>

#include "output_generator.hpp"
#include "web_writer.hpp"

namespace prism::shaderc {
namespace {

class WebCatalogueGenerator final : public OutputGenerator {
  public:
    std::string_view name() const override { return "web catalogue"; }

    std::vector<std::string> pathsNamed(const Options& o) const override {
        if (o.emitWeb.empty()) return {};
        return {o.emitWeb};
    }

    std::vector<GeneratedFile> generate(const Options& o, const ResolvedCatalog& rc) const override {
        return {{o.emitWeb, writeWebCatalogue(rc.data, std::filesystem::path(o.emitWeb).stem().string())}};
    }
};

}  // namespace

std::unique_ptr<OutputGenerator> makeWebCatalogueGenerator() {
    return std::make_unique<WebCatalogueGenerator>();
}

}  // namespace prism::shaderc
