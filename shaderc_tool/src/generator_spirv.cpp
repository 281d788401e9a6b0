// The output generator of --emit-spirv DIR (output_generator.hpp): each stage's SPIR-V as a .spv file.
#include "glsl_emitter.hpp"
#include "output_generator.hpp"

namespace prism::shaderc {
namespace {

class SpirvFilesGenerator final : public OutputGenerator {
  public:
    std::string_view name() const override { return "SPIR-V files"; }

    std::vector<std::string> pathsNamed(const Options& o) const override {
        if (o.emitSpirvDir.empty()) return {};
        return {o.emitSpirvDir};
    }

    std::vector<GeneratedFile> generate(const Options& o, const ResolvedCatalog& rc) const override {
        return spirvFiles(o.emitSpirvDir, rc.data);
    }
};

}  // namespace

std::unique_ptr<OutputGenerator> makeSpirvFilesGenerator() {
    return std::make_unique<SpirvFilesGenerator>();
}

}  // namespace prism::shaderc
