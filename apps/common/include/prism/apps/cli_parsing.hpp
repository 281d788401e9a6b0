// Strict parsing of the numbers prism-render takes on its command line
// ("x,y,z" vectors, "WxH" sizes, finite floats): a bad value gives a message saying
// what was expected instead of a silently defaulted number.
#pragma once

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <utility>

namespace prism::apps {

std::optional<float> parseFiniteFloat(const std::string& text);
std::optional<glm::vec3> parseVec3(const std::string& text);            // "x,y,z"
std::optional<std::pair<int, int>> parseSize(const std::string& text);  // "WxH", 1..16384

}  // namespace prism::apps
