// --script FILE: key and parameter events played one line per frame, for tests and demos.
//
//     # comment
//     key S                         the S key (also M, plus, minus, left, right, up, down, escape)
//     shader gouraud                pick a catalogue shader
//     variant BLINN=1               pick an axis value
//     scene examples/scenes/rain.json   open a scene (relative paths: to the script's folder
//                                   first, then the working directory); "scene none" closes it
//     set rain.intensity heavy      any viewer_actions.hpp parameter
//     wait 3                        three frames with no event
//     expect phong BLINN=1          the program in use after this frame contains the text;
//                                   otherwise the viewer prints the error and exits 1
//
// A malformed line is a GCC-style error `FILE:LINE:1: error: ...` (exit 2).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace prism::viewer {

struct ScriptEvent {
    int line = 0;
    std::string command;  // key, shader, variant, scene, set, wait, expect
    std::string argument;
    std::string value;  // set's value
};

class ViewerScript {
  public:
    static ViewerScript load(const std::string& path);  // throws std::runtime_error (GCC style)
    // The next event, or nullopt when a wait is running or the script has ended.
    std::optional<ScriptEvent> next();
    bool finished() const { return at_ >= events_.size() && waiting_ == 0; }
    const std::string& path() const { return path_; }
    std::string resolve(const std::string& file) const;  // a scene path, as the script means it

  private:
    std::string path_;
    std::vector<ScriptEvent> events_;
    std::size_t at_ = 0;
    int waiting_ = 0;
};

}  // namespace prism::viewer
