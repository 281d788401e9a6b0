// Reading a scene from JSON (nlohmann/json), with errors that name the file, the JSON
// path and what was expected, e.g.
//     scenes/bad.json: /lights/2/direction: expected 3 numbers
//     scenes/bad.json:4:17: syntax error while parsing object - unexpected '}'
// Unknown keys are errors too (a misspelled "fogg" must not be silently ignored).
//
// Usage (snippet: examples/snippets/scene_scene_loader.cpp):
//
//     #include "prism/scene/scene_loader.hpp"
//     prism::scene::Scene scene = prism::scene::loadScene("examples/scenes/one_light.json");
//     prism::scene::Scene same = prism::scene::parseScene(text, "inline.json");
#pragma once

#include <stdexcept>
#include <string>

#include "prism/scene/scene.hpp"

namespace prism::scene {

class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

Scene loadScene(const std::string& path);
Scene parseScene(const std::string& text, const std::string& fileName);

}  // namespace prism::scene
