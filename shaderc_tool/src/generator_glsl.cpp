// The output generator of --emit-glsl DIR (output_generator.hpp): each target's flattened stage texts.
#include "glsl_emitter.hpp"
#include "output_generator.hpp"
#include "shader_targets.hpp"

namespace prism::shaderc {
namespace {

class GlslTextsGenerator final : public OutputGenerator {
  public:
    std::string_view name() const override { return "GLSL texts"; }

    std::vector<std::string> pathsNamed(const Options& o) const override {
        if (o.emitGlslDir.empty()) return {};
        return {o.emitGlslDir};
    }

    std::vector<GeneratedFile> generate(const Options& o, const ResolvedCatalog& rc) const override {
        std::vector<std::vector<Target>> targets(rc.data.shaders.size());
        for (std::size_t s = 0; s < targets.size(); ++s)
            for (const Target t : o.targets)
                if (producedFor(o, rc, s, t)) targets[s].push_back(t);
        return glslFiles(o.emitGlslDir, rc.data, o.targets, targets);
    }
};

}  // namespace

std::unique_ptr<OutputGenerator> makeGlslTextsGenerator() {
    return std::make_unique<GlslTextsGenerator>();
}

}  // namespace prism::shaderc
