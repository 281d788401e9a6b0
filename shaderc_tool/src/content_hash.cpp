// Content hashes and token signatures (see content_hash.hpp).
#include "content_hash.hpp"

#include <cstdio>

namespace prism::shaderc {

ContentHash& ContentHash::add(std::string_view part) {
    auto step = [&](unsigned char c) {
        a_ = (a_ ^ c) * 1099511628211ull;
        b_ = (b_ ^ c) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
        b_ ^= b_ >> 29;
    };
    for (unsigned char c : part) step(c);
    const auto n = static_cast<std::uint64_t>(part.size());
    for (int i = 0; i < 8; ++i) step(static_cast<unsigned char>(n >> (8 * i)));
    step(0xff);
    return *this;
}

std::string ContentHash::hex() const {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(a_),
                  static_cast<unsigned long long>(b_));
    return buf;
}

std::string tokenSignature(std::string_view preprocessed) {
    ContentHash hash;
    std::string line;
    std::size_t start = 0;
    while (start < preprocessed.size()) {
        std::size_t end = preprocessed.find('\n', start);
        if (end == std::string_view::npos) end = preprocessed.size();
        line.clear();
        bool blank = false;
        for (std::size_t i = start; i < end; ++i) {
            const char c = preprocessed[i];
            const bool space = c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
            if (space) {
                blank = !line.empty();
            } else {
                if (blank) line += ' ';
                blank = false;
                line += c;
            }
        }
        if (!line.empty() && !line.starts_with("#line")) hash.add(line);
        start = end + 1;
    }
    return hash.hex();
}

}  // namespace prism::shaderc
