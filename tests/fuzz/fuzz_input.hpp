// Helpers shared by the libFuzzer harnesses of tests/fuzz: the fuzzer's bytes as text,
// split into parts, or as a file that path-based loaders can open (an anonymous
// memfd, so no harness touches the disk).
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace prism::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// Splits at each `separator` line ("\n//--\n" style), at most `maxParts` parts.
inline std::vector<std::string> splitParts(std::string_view all, std::string_view separator, std::size_t maxParts) {
    std::vector<std::string> parts;
    while (parts.size() + 1 < maxParts) {
        const auto at = all.find(separator);
        if (at == std::string_view::npos) break;
        parts.emplace_back(all.substr(0, at));
        all.remove_prefix(at + separator.size());
    }
    parts.emplace_back(all);
    return parts;
}

// The bytes as an unlinked in-memory file, readable at path() while it lives.
class MemoryFile {
  public:
    MemoryFile(const std::uint8_t* data, std::size_t size) : fd_(memfd_create("prism-fuzz", 0)) {
        if (fd_ < 0) {
            std::perror("memfd_create");
            std::abort();
        }
        std::size_t done = 0;
        while (done < size) {
            const ssize_t n = write(fd_, data + done, size - done);
            if (n <= 0) {
                std::perror("write");
                std::abort();
            }
            done += static_cast<std::size_t>(n);
        }
        path_ = "/proc/self/fd/" + std::to_string(fd_);
    }
    ~MemoryFile() { close(fd_); }
    MemoryFile(const MemoryFile&) = delete;
    MemoryFile& operator=(const MemoryFile&) = delete;
    const std::string& path() const { return path_; }

  private:
    int fd_;
    std::string path_;
};

}  // namespace prism::fuzz
