// The line-by-line OBJ pre-validation (see obj_validation.hpp).
#include "obj_validation.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <vector>

namespace prism::geometry::detail {

namespace {

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        if (end == text.size()) break;
        start = end + 1;
    }
    return lines;
}

std::vector<std::string_view> splitTokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

bool isFiniteNumber(std::string_view token) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseInteger(std::string_view token, std::int64_t& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    return error == std::errc() && end == token.data() + token.size();
}

struct ElementCounts {
    std::int64_t positions = 0, texcoords = 0, normals = 0;
};

const char* const kElementNames[3] = {"position", "texture coordinate", "normal"};

// Checks one index of a face corner; `kind` 0 = v, 1 = vt, 2 = vn.
std::optional<std::string> checkIndex(std::string_view token, int kind, std::int64_t totalInFile,
                                      std::int64_t definedSoFar) {
    const std::string name = kElementNames[kind];
    std::int64_t index = 0;
    if (!parseInteger(token, index)) return name + " index '" + std::string(token) + "' is not an integer";
    if (index == 0) return name + " index 0 is invalid: OBJ indices start at 1";
    if (index > totalInFile)
        return name + " index " + std::to_string(index) + " is out of range: the file defines " +
               std::to_string(totalInFile) + " " + name + (totalInFile == 1 ? "" : "s");
    if (index < 0 && index < -definedSoFar)  // not -index: INT64_MIN has no negation
        return "relative " + name + " index " + std::to_string(index) + " reaches before the first " + name + " (" +
               std::to_string(definedSoFar) + " defined so far)";
    return std::nullopt;
}

std::optional<std::string> checkFaceCorner(std::string_view corner, const ElementCounts& total,
                                           const ElementCounts& soFar) {
    std::string_view parts[3];
    int partCount = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t slash = corner.find('/', start);
        if (partCount == 3) return "face corner '" + std::string(corner) + "' has more than 3 parts (v/vt/vn)";
        parts[partCount++] =
            corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
    }
    if (parts[0].empty()) return "face corner '" + std::string(corner) + "' has no position index";
    if (auto problem = checkIndex(parts[0], 0, total.positions, soFar.positions)) return problem;
    if (partCount >= 2 && !parts[1].empty())
        if (auto problem = checkIndex(parts[1], 1, total.texcoords, soFar.texcoords)) return problem;
    if (partCount == 3) {
        if (parts[2].empty()) return "face corner '" + std::string(corner) + "' ends with '/' but has no normal index";
        if (auto problem = checkIndex(parts[2], 2, total.normals, soFar.normals)) return problem;
    }
    return std::nullopt;
}

// Checks the numbers of a `v`/`vt`/`vn` statement. (Messages are appended piecewise:
// GCC 12 warns falsely about `"literal" + std::string` chains here, -Wrestrict.)
std::optional<std::string> checkNumbers(const std::vector<std::string_view>& tokens, bool (*countIsValid)(std::size_t),
                                        const char* expectation) {
    std::string message = "`";
    message.append(tokens[0]).append("` needs ").append(expectation).append(", got ");
    for (std::size_t i = 1; i < tokens.size(); ++i)
        if (!isFiniteNumber(tokens[i]))
            return message.append("'").append(tokens[i]).append("', which is not a finite number");
    const std::size_t count = tokens.size() - 1;
    if (!countIsValid(count)) return message.append(std::to_string(count)).append(count == 1 ? " number" : " numbers");
    return std::nullopt;
}

}  // namespace

std::optional<ObjProblem> findFirstObjProblem(std::string_view text) {
    const std::vector<std::string_view> lines = splitLines(text);

    ElementCounts total;
    for (std::string_view line : lines) {
        const std::vector<std::string_view> tokens = splitTokens(line);
        if (tokens.empty()) continue;
        if (tokens[0] == "v")
            ++total.positions;
        else if (tokens[0] == "vt")
            ++total.texcoords;
        else if (tokens[0] == "vn")
            ++total.normals;
    }

    ElementCounts soFar;
    for (std::size_t n = 0; n < lines.size(); ++n) {
        const std::vector<std::string_view> tokens = splitTokens(lines[n]);
        if (tokens.empty() || tokens[0].front() == '#') continue;
        std::optional<std::string> problem;
        if (tokens[0] == "v") {
            problem = checkNumbers(
                tokens, [](std::size_t c) { return c == 3 || c == 4 || c == 6; },
                "3 numeric coordinates (x y z, x y z w or x y z r g b)");
            ++soFar.positions;
        } else if (tokens[0] == "vn") {
            problem = checkNumbers(
                tokens, [](std::size_t c) { return c == 3; }, "3 numeric components (x y z)");
            ++soFar.normals;
        } else if (tokens[0] == "vt") {
            problem = checkNumbers(
                tokens, [](std::size_t c) { return c >= 1 && c <= 3; }, "1 to 3 numeric coordinates (u [v [w]])");
            ++soFar.texcoords;
        } else if (tokens[0] == "f") {
            if (tokens.size() < 4) problem = "`f` needs at least 3 corners, got " + std::to_string(tokens.size() - 1);
            if (tokens.size() - 1 > kMaxFaceCorners)
                problem = "`f` has " + std::to_string(tokens.size() - 1) + " corners, more than the limit of " +
                          std::to_string(kMaxFaceCorners) + " per face; split the polygon";
            for (std::size_t i = 1; !problem && i < tokens.size(); ++i)
                problem = checkFaceCorner(tokens[i], total, soFar);
        }
        if (problem) return ObjProblem{n + 1, *problem};
    }
    return std::nullopt;
}

}  // namespace prism::geometry::detail
