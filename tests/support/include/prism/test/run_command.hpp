// The one way Prism's tests run a command-line program (tests/README.md): every app's CLI
// tests and the flags check call runCommand and assert on its exit code, stdout and stderr.
// The program is executed directly (no shell), so arguments need no quoting; a test that
// wants a shell pipeline passes {"/bin/sh", "-c", "..."}.
//
//     #include "prism/test/run_command.hpp"
//
//     TEST(PrismBluenoiseCli, UnknownFlagIsAUsageError) {
//         const auto r = prism::test::runCommand({PRISM_BLUENOISE_CLI, "generate", "--bogus"});
//         EXPECT_EQ(r.exitCode, 2) << r;
//         EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r;
//     }
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace prism::test {

struct CommandResult {
    std::vector<std::string> args;
    int exitCode = -1;  // the program's exit status; -1 when a signal ended it or it could not start
    std::string out;    // stdout (and stderr too with mergeStderr)
    std::string err;    // stderr
};

struct CommandOptions {
    std::filesystem::path workDir;  // empty: this process's working directory
    bool mergeStderr = false;       // stderr into `out`, interleaved as `2>&1` would
};

// Runs args[0] (a path, or a name looked up in PATH) with the rest as its arguments and
// waits for it. Throws std::runtime_error when no process can be started at all.
CommandResult runCommand(const std::vector<std::string>& args, const CommandOptions& options = {});

// "`a b c` exited 2\nstdout:\n...\nstderr:\n...": what a failed assertion should show.
std::ostream& operator<<(std::ostream& os, const CommandResult& result);

}  // namespace prism::test
