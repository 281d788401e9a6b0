// Depfile text generation (see depfile.hpp).
#include "depfile.hpp"

#include <algorithm>

namespace prism::shaderc {

std::string escapeDepfilePath(const std::string& path) {
    std::string out;
    out.reserve(path.size());
    for (char c : path) {
        switch (c) {
            case ' ': out += "\\ "; break;
            case '$': out += "$$"; break;
            case '#': out += "\\#"; break;
            default: out += c;
        }
    }
    return out;
}

std::string makeDepfile(const std::string& target, std::vector<std::string> dependencies) {
    std::sort(dependencies.begin(), dependencies.end());
    dependencies.erase(std::unique(dependencies.begin(), dependencies.end()), dependencies.end());
    std::string out = escapeDepfilePath(target) + ":";
    for (const auto& d : dependencies) out += " \\\n  " + escapeDepfilePath(d);
    out += "\n";
    return out;
}

}  // namespace prism::shaderc
