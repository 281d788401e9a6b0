// Test helper: runs the real prism-shaderc executable (through prism::test::runCommand) and
// captures its exit code and output, and builds scratch directories of GLSL files for it.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "prism/test/run_command.hpp"

namespace prism::test {

struct ToolRun {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// A shell command line (quoting as the shell reads it), in `workDir` when not empty.
inline ToolRun runShell(const std::string& commandLine, const std::string& workDir = "") {
    const auto r = runCommand({"/bin/sh", "-c", commandLine}, {.workDir = workDir, .mergeStderr = true});
    return {r.exitCode, r.out};
}

// The real prism-shaderc with `args`, written as on a shell command line.
inline ToolRun runShaderc(const std::string& args, const std::string& workDir = "") {
    return runShell(std::string(PRISM_SHADERC_EXE) + " " + args, workDir);
}

inline std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// How many times `what` occurs in `text` (overlaps counted): "printed once" checks.
inline std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

inline void writeFile(const std::filesystem::path& p, const std::string& text) {
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

// A fresh directory under the system temp dir, removed when the object dies.
class ScratchDir {
  public:
    explicit ScratchDir(const std::string& name)
        : path_(std::filesystem::temp_directory_path() / ("prism-test-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() { std::filesystem::remove_all(path_); }
    const std::filesystem::path& path() const { return path_; }
    std::string str() const { return path_.string(); }
    void write(const std::string& relative, const std::string& text) const { writeFile(path_ / relative, text); }

  private:
    std::filesystem::path path_;
};

}  // namespace prism::test
