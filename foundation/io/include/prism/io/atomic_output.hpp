// Cleanup for outputs written atomically (to `<target><marker><pid>`, then renamed): the
// temp files of writers that were killed mid-write. Shared by prism-shaderc's outputs and
// prism_image's PNG writer (header-only, CPU only, POSIX).
//
// Usage (snippet: examples/snippets/io_atomic_output.cpp):
//
//     #include "prism/io/atomic_output.hpp"
//     // before or after writing out/scene.png through out/scene.png.tmp-<pid>:
//     prism::io::removeStaleTemps("out/scene.png", ".tmp-");
#pragma once

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace prism::io {

// Removes `<name><marker><pid>` files beside `target` whose writer process no longer
// exists; a live writer's temp file (and this process's own) is kept. Never throws.
inline void removeStaleTemps(const std::filesystem::path& target, std::string_view marker) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string prefix = target.filename().string() + std::string(marker);
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() || name.size() > prefix.size() + 9 ||
            name.compare(0, prefix.size(), prefix) != 0)
            continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
        const auto pid = static_cast<pid_t>(std::stol(digits));
        std::error_code ignored;
        if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH) fs::remove(it->path(), ignored);
    }
}

}  // namespace prism::io
