// The output generator of -o X.hpp (output_generator.hpp): the C++ header and its data file X.cpp.
#include <filesystem>

#include "data_writer.hpp"
#include "header_writer.hpp"
#include "output_generator.hpp"

namespace prism::shaderc {
namespace {

class HeaderGenerator final : public OutputGenerator {
  public:
    std::string_view name() const override { return "C++ header and data file"; }

    std::vector<std::string> pathsNamed(const Options& o) const override {
        if (o.output.empty()) return {};
        return {o.output, dataPathFor(o.output)};
    }

    std::vector<GeneratedFile> generate(const Options& o, const ResolvedCatalog& rc) const override {
        const auto fileName = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
        const std::string data = dataPathFor(o.output);
        std::string header = writeHeader(rc.data, fileName(data));
        std::string dataText = writeData(rc.data, fileName(o.output), header);
        return {{o.output, std::move(header)}, {data, std::move(dataText)}};
    }
};

}  // namespace

std::unique_ptr<OutputGenerator> makeHeaderGenerator() {
    return std::make_unique<HeaderGenerator>();
}

}  // namespace prism::shaderc
