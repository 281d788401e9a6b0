// runCommand (prism/test/run_command.hpp): fork and exec with stdout and stderr on two
// pipes, read together with poll() so that neither pipe can fill and stall the child.
#include "prism/test/run_command.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace prism::test {
namespace {

struct Pipe {
    int read = -1, write = -1;
    Pipe() {
        int fds[2];
        if (::pipe(fds) != 0) throw std::runtime_error(std::string("runCommand: pipe: ") + std::strerror(errno));
        read = fds[0];
        write = fds[1];
    }
};

// In the child: redirect, change directory, exec; only async-signal-safe calls until exec.
[[noreturn]] void execChild(const std::vector<std::string>& args, const CommandOptions& options, const Pipe& out,
                            const Pipe& err) {
    ::dup2(out.write, STDOUT_FILENO);
    ::dup2(options.mergeStderr ? out.write : err.write, STDERR_FILENO);
    for (int fd : {out.read, out.write, err.read, err.write}) ::close(fd);
    if (!options.workDir.empty() && ::chdir(options.workDir.c_str()) != 0) ::_exit(127);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
}

// Reads both pipes until both are closed.
void readBoth(int outFd, int errFd, std::string& out, std::string& err) {
    std::array<pollfd, 2> fds{{{outFd, POLLIN, 0}, {errFd, POLLIN, 0}}};
    std::string* sinks[2] = {&out, &err};
    std::array<char, 4096> buffer{};
    int open = 2;
    while (open > 0) {
        if (::poll(fds.data(), fds.size(), -1) < 0) {
            if (errno == EINTR) continue;
            throw std::runtime_error(std::string("runCommand: poll: ") + std::strerror(errno));
        }
        for (std::size_t i = 0; i < fds.size(); ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0) continue;
            const ssize_t n = ::read(fds[i].fd, buffer.data(), buffer.size());
            if (n > 0) {
                sinks[i]->append(buffer.data(), static_cast<std::size_t>(n));
            } else if (n == 0 || errno != EINTR) {
                ::close(fds[i].fd);
                fds[i].fd = -1;
                --open;
            }
        }
    }
}

}  // namespace

CommandResult runCommand(const std::vector<std::string>& args, const CommandOptions& options) {
    if (args.empty()) throw std::invalid_argument("runCommand: no program given");
    CommandResult result;
    result.args = args;
    const Pipe out, err;
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("runCommand: fork: ") + std::strerror(errno));
    if (pid == 0) execChild(args, options, out, err);
    ::close(out.write);
    ::close(err.write);
    readBoth(out.read, err.read, result.out, result.err);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::ostream& operator<<(std::ostream& os, const CommandResult& result) {
    os << '`';
    for (std::size_t i = 0; i < result.args.size(); ++i) os << (i ? " " : "") << result.args[i];
    return os << "` exited " << result.exitCode << "\nstdout:\n" << result.out << "\nstderr:\n" << result.err;
}

}  // namespace prism::test
