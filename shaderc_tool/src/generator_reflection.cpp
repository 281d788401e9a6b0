// The output generator of --emit-reflection FILE.json (output_generator.hpp): reflection_writer.hpp's JSON.
#include "output_generator.hpp"
#include "reflection_writer.hpp"

namespace prism::shaderc {
namespace {

class ReflectionJsonGenerator final : public OutputGenerator {
  public:
    std::string_view name() const override { return "reflection JSON"; }

    std::vector<std::string> pathsNamed(const Options& o) const override {
        if (o.emitReflection.empty()) return {};
        return {o.emitReflection};
    }

    std::vector<GeneratedFile> generate(const Options& o, const ResolvedCatalog& rc) const override {
        return {{o.emitReflection, writeReflectionJson(rc.data)}};
    }
};

}  // namespace

std::unique_ptr<OutputGenerator> makeReflectionJsonGenerator() {
    return std::make_unique<ReflectionJsonGenerator>();
}

}  // namespace prism::shaderc
