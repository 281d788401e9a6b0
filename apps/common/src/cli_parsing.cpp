// Number parsing for the command-line programs (see cli_parsing.hpp).
#include "prism/apps/cli_parsing.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace prism::apps {

std::optional<float> parseFiniteFloat(const std::string& text) {
    if (text.empty()) return std::nullopt;
    float value = 0.0f;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<glm::vec3> parseVec3(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ',');) parts.push_back(p);
    if (parts.size() != 3 || text.back() == ',') return std::nullopt;
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
        auto f = parseFiniteFloat(parts[static_cast<std::size_t>(i)]);
        if (!f) return std::nullopt;
        v[i] = *f;
    }
    return v;
}

std::optional<std::pair<int, int>> parseSize(const std::string& text) {
    auto x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    int w = 0, h = 0;
    auto [e1, ec1] = std::from_chars(text.data(), text.data() + x, w);
    auto [e2, ec2] = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
    if (ec1 != std::errc() || ec2 != std::errc() || e1 != text.data() + x || e2 != text.data() + text.size())
        return std::nullopt;
    if (w < 1 || h < 1 || w > 16384 || h > 16384) return std::nullopt;
    return std::make_pair(w, h);
}

}  // namespace prism::apps
