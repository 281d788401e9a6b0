// The running build's identity (tool_identity.hpp).
#include "tool_identity.hpp"

#include <filesystem>

#include <glslang/Public/ShaderLang.h>

namespace prism::shaderc {

const std::string& toolIdentity() {
    static const std::string identity = [] {
        const auto v = glslang::GetVersion();
        std::string id = std::string(PRISM_VERSION) + " glslang " + std::to_string(v.major) + "." +
                         std::to_string(v.minor) + "." + std::to_string(v.patch);
        std::error_code ec;
        const auto exe = std::filesystem::canonical("/proc/self/exe", ec);
        if (!ec) {
            const auto size = std::filesystem::file_size(exe, ec);
            const auto time = std::filesystem::last_write_time(exe, ec).time_since_epoch().count();
            if (!ec) id += " " + std::to_string(size) + " " + std::to_string(time);
        }
        return id;
    }();
    return identity;
}

std::string stampText() {
    return "prism-shaderc " + toolIdentity() + "\n";
}

}  // namespace prism::shaderc
