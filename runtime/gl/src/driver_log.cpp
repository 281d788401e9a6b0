// Rewrites driver log lines (Mesa, NVIDIA, AMD shapes) to `path:line[:column]: message`.
#include "prism/gl/driver_log.hpp"

#include <cctype>
#include <optional>

namespace prism::gl {
namespace {

// Reads an unsigned decimal at `pos`, advancing it; nullopt without digits.
std::optional<std::uint32_t> readNumber(std::string_view s, std::size_t& pos) {
    const std::size_t start = pos;
    std::uint64_t v = 0;
    while (pos < s.size() && std::isdigit(static_cast<unsigned char>(s[pos])) && pos - start < 9)
        v = v * 10 + static_cast<std::uint64_t>(s[pos++] - '0');
    if (pos == start) return std::nullopt;
    return static_cast<std::uint32_t>(v);
}

bool consume(std::string_view s, std::size_t& pos, std::string_view token) {
    if (s.substr(pos, token.size()) != token) return false;
    pos += token.size();
    return true;
}

const std::string* pathOf(std::span<const SourceName> files, std::uint32_t number) {
    for (const auto& f : files)
        if (f.number == number) return &f.path;
    return nullptr;
}

struct Location {
    std::uint32_t source = 0, line = 0;
    std::optional<std::uint32_t> column;
    std::string prefix;  // inserted before the message, e.g. "error: " for AMD's "ERROR:"
    std::string_view message;
};

// Mesa: "0:12(3): error: ..."
std::optional<Location> parseMesa(std::string_view s) {
    std::size_t p = 0;
    Location loc;
    auto src = readNumber(s, p);
    if (!src || !consume(s, p, ":")) return std::nullopt;
    auto line = readNumber(s, p);
    if (!line || !consume(s, p, "(")) return std::nullopt;
    auto col = readNumber(s, p);
    if (!col || !consume(s, p, "):")) return std::nullopt;
    consume(s, p, " ");
    loc.source = *src;
    loc.line = *line;
    loc.column = *col;
    loc.message = s.substr(p);
    return loc;
}

// NVIDIA: "0(12) : error C0000: ..."
std::optional<Location> parseNvidia(std::string_view s) {
    std::size_t p = 0;
    Location loc;
    auto src = readNumber(s, p);
    if (!src || !consume(s, p, "(")) return std::nullopt;
    auto line = readNumber(s, p);
    if (!line || !consume(s, p, ")")) return std::nullopt;
    if (!consume(s, p, " : ") && !consume(s, p, ": ")) return std::nullopt;
    loc.source = *src;
    loc.line = *line;
    loc.message = s.substr(p);
    return loc;
}

// AMD / glslang: "ERROR: 0:12: ..." or "WARNING: 0:12: ..."
std::optional<Location> parseAmd(std::string_view s) {
    std::size_t p = 0;
    Location loc;
    if (consume(s, p, "ERROR: "))
        loc.prefix = "error: ";
    else if (consume(s, p, "WARNING: "))
        loc.prefix = "warning: ";
    else
        return std::nullopt;
    auto src = readNumber(s, p);
    if (!src || !consume(s, p, ":")) return std::nullopt;
    auto line = readNumber(s, p);
    if (!line || !consume(s, p, ":")) return std::nullopt;
    consume(s, p, " ");
    loc.source = *src;
    loc.line = *line;
    loc.message = s.substr(p);
    return loc;
}

std::string translateLine(std::string_view line, std::span<const SourceName> files) {
    std::optional<Location> loc = parseMesa(line);
    if (!loc) loc = parseNvidia(line);
    if (!loc) loc = parseAmd(line);
    if (!loc) return std::string(line);
    const std::string* path = pathOf(files, loc->source);
    if (!path) return std::string(line);
    std::string out = *path;
    out += ':';
    out += std::to_string(loc->line);
    if (loc->column) {
        out += ':';
        out += std::to_string(*loc->column);
    }
    out += ": ";
    out += loc->prefix;
    out += loc->message;
    return out;
}

}  // namespace

std::string translateDriverLog(std::string_view log, std::span<const SourceName> files) {
    std::string out;
    std::size_t start = 0;
    while (start < log.size()) {
        std::size_t end = log.find('\n', start);
        const bool lastLine = end == std::string_view::npos;
        if (lastLine) end = log.size();
        out += translateLine(log.substr(start, end - start), files);
        if (!lastLine) out += '\n';
        start = end + 1;
    }
    return out;
}

}  // namespace prism::gl
