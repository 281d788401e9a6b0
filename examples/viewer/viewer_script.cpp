// Loading and stepping a --script file (viewer_script.hpp).
#include "viewer_script.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace prism::viewer {

ViewerScript ViewerScript::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ":1:1: error: cannot read the script");
    ViewerScript script;
    script.path_ = path;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        const auto hash = text.find('#');
        if (hash != std::string::npos) text.erase(hash);
        text.erase(text.find_last_not_of(" \t\r") + 1);
        std::istringstream words(text);
        ScriptEvent e;
        e.line = line;
        if (!(words >> e.command)) continue;
        auto fail = [&](const std::string& message) {
            throw std::runtime_error(path + ":" + std::to_string(line) + ":1: error: " + message);
        };
        if (e.command == "set") {
            if (!(words >> e.argument >> e.value)) fail("'set' wants NAME VALUE");
        } else if (e.command == "expect") {
            std::getline(words >> std::ws, e.argument);
            if (e.argument.empty()) fail("'expect' wants the text of the program in use");
        } else if (e.command == "key" || e.command == "shader" || e.command == "variant" || e.command == "scene" ||
                   e.command == "wait") {
            if (!(words >> e.argument)) fail("'" + e.command + "' wants an argument");
            if (e.command == "wait" && e.argument.find_first_not_of("0123456789") != std::string::npos)
                fail("'wait' wants a frame count");
        } else {
            fail("unknown event '" + e.command + "' (key, shader, variant, scene, set, wait, expect)");
        }
        std::string extra;
        if (e.command != "expect" && (words >> extra)) fail("unexpected '" + extra + "'");
        script.events_.push_back(e);
    }
    return script;
}

std::optional<ScriptEvent> ViewerScript::next() {
    if (waiting_ > 0) {
        --waiting_;
        return std::nullopt;
    }
    if (at_ >= events_.size()) return std::nullopt;
    ScriptEvent e = events_[at_++];
    if (e.command == "wait") waiting_ = std::stoi(e.argument);
    return e;
}

std::string ViewerScript::resolve(const std::string& file) const {
    namespace fs = std::filesystem;
    const fs::path beside = fs::path(path_).parent_path() / file;
    if (fs::path(file).is_relative() && fs::exists(beside)) return beside.string();
    return file;
}

}  // namespace prism::viewer
