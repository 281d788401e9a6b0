// Atomic, change-only file writes (see output_file.hpp).
#include "prism/io/atomic_output.hpp"
#include "output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <signal.h>
#include <unistd.h>

namespace prism::shaderc {
namespace fs = std::filesystem;

void removeStaleTemps(const fs::path& target) {
    io::removeStaleTemps(target, ".tmp.");
}

namespace {

bool sameContent(const std::string& path, const std::string& content) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    in.seekg(0, std::ios::end);
    if (static_cast<std::size_t>(in.tellg()) != content.size()) return false;
    in.seekg(0);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str() == content;
}
}  // namespace

WriteOutcome writeIfChanged(const std::string& path, const std::string& content, std::string& error) {
    std::error_code ec;
    fs::path target(path);
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    removeStaleTemps(target);
    if (sameContent(path, content)) return WriteOutcome::Unchanged;
    fs::path temp = target;
    temp += ".tmp." + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) {
            error = path + ": cannot write (" + std::strerror(errno) + "); check the directory exists and is writable";
            return WriteOutcome::Failed;
        }
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        out.close();  // a full disk may only show when the last buffer is written
        if (!out) {
            error = path + ": write failed (" + std::strerror(errno) + ")";
            fs::remove(temp, ec);
            return WriteOutcome::Failed;
        }
    }
    fs::rename(temp, target, ec);
    if (ec) {
        error = path + ": cannot replace (" + ec.message() + ")";
        fs::remove(temp, ec);
        return WriteOutcome::Failed;
    }
    return WriteOutcome::Written;
}

bool touchFile(const std::string& path, const std::string& content, std::string& error) {
    const auto outcome = writeIfChanged(path, content, error);
    if (outcome != WriteOutcome::Unchanged) return outcome == WriteOutcome::Written;
    std::error_code ec;
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec);
    if (ec) {
        error = path + ": cannot update the time stamp (" + ec.message() + ")";
        return false;
    }
    return true;
}

}  // namespace prism::shaderc
