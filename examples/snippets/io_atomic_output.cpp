// The usage example of prism/io/atomic_output.hpp, compiled and run by tests/snippets:
// a dead writer's temp file is removed, this process's own is kept.
#include <fstream>

// [snippet]
#include "prism/io/atomic_output.hpp"
// [/snippet]

int main() {
    namespace fs = std::filesystem;
    fs::create_directories("out");
    std::ofstream("out/scene.png.tmp-999999999").put('x');  // no such process
    const fs::path mine = "out/scene.png.tmp-" + std::to_string(::getpid());
    std::ofstream(mine).put('x');
    // [snippet]
    // before or after writing out/scene.png through out/scene.png.tmp-<pid>:
    prism::io::removeStaleTemps("out/scene.png", ".tmp-");
    // [/snippet]
    const bool ok = !fs::exists("out/scene.png.tmp-999999999") && fs::exists(mine);
    fs::remove(mine);
    return ok ? 0 : 1;
}
