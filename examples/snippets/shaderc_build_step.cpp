// The usage example of prism/shaderc/build_step.hpp, compiled and run by tests/snippets.
#include <string>
#include <utility>

// [snippet]
#include "prism/shaderc/build_step.hpp"
// [/snippet]

int main() {
    // [snippet]
    namespace sc = prism::shaderc;
    const std::pair<std::string, std::string> files[] = {
        {"shaders/tint.frag", "#include \"lib/tint.glsl\"\nout vec4 frag;\nvoid main() { frag = tint(); }\n"},
        {"shaders/lib/tint.glsl", "vec4 tint() { return vec4(1.0, 0.5, 0.5, 1.0); }\n"}};
    const sc::Files memory = sc::Files::memory(files);
    const sc::StageResolution stage = sc::resolveStage("shaders/tint.frag", {}, memory);
    // stage.ok; stage.resolved.files: shaders/tint.frag, shaders/lib/tint.glsl
    // sc::moduleId("lib/tint.glsl") == "lib__tint"
    // [/snippet]
    const bool filesOk = stage.resolved.files.size() == 2 && stage.resolved.files[1] == "shaders/lib/tint.glsl";
    return stage.ok && filesOk && sc::moduleId("lib/tint.glsl") == "lib__tint" ? 0 : 1;
}
