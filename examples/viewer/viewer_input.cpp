// Keys and --script events, both turned into viewer_actions.hpp calls (viewer_input.hpp).
#include "viewer_input.hpp"

#include <iostream>
#include <stdexcept>

#include "prism/gl/gl.hpp"  // the GL loader first: GLFW must not pull in <GL/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "imgui_layer.hpp"
#include "variant_choice.hpp"
#include "viewer_actions.hpp"

namespace prism::viewer {

namespace {

// A key as the keyboard or a script's `key NAME` presses it.
void pressKey(ViewerState& s, const catalog::Catalog& catalog, GLFWwindow* window, int key) {
    auto& c = s.catalogue;
    switch (key) {
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window, GLFW_TRUE); break;
        case GLFW_KEY_LEFT: c.yaw -= 0.1f; break;
        case GLFW_KEY_RIGHT: c.yaw += 0.1f; break;
        case GLFW_KEY_UP: c.pitch -= 0.1f; break;
        case GLFW_KEY_DOWN: c.pitch += 0.1f; break;
        case GLFW_KEY_S: nextShader(s, catalog); break;
        case GLFW_KEY_M: nextMesh(s); break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            if (c.subdivision < 6) setParameter(s, "subdivision", std::to_string(c.subdivision + 1));
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            if (c.subdivision > 0) setParameter(s, "subdivision", std::to_string(c.subdivision - 1));
            break;
        default: break;
    }
}

int keyNamed(const std::string& name) {
    if (name.size() == 1 && name[0] >= 'A' && name[0] <= 'Z') return GLFW_KEY_A + (name[0] - 'A');
    if (name == "plus") return GLFW_KEY_EQUAL;
    if (name == "minus") return GLFW_KEY_MINUS;
    if (name == "left") return GLFW_KEY_LEFT;
    if (name == "right") return GLFW_KEY_RIGHT;
    if (name == "up") return GLFW_KEY_UP;
    if (name == "down") return GLFW_KEY_DOWN;
    if (name == "escape") return GLFW_KEY_ESCAPE;
    throw std::invalid_argument("unknown key '" + name + "' (A-Z, plus, minus, left, right, up, down, escape)");
}

}  // namespace

void installKeyHandler(GLFWwindow* window, ViewerState& state, const catalog::Catalog& catalog) {
    static const catalog::Catalog* gCatalog = nullptr;  // GLFW's callback takes no closure
    gCatalog = &catalog;
    glfwSetWindowUserPointer(window, &state);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_RELEASE || ImGuiLayer::wantsKeyboard()) return;
        pressKey(*static_cast<ViewerState*>(glfwGetWindowUserPointer(w)), *gCatalog, w, key);
    });
}

// Applies one script event; the `expect` text is returned for the check after the frame.
std::string applyEvent(ViewerState& state, const catalog::Catalog& catalog, GLFWwindow* window,
                       const ViewerScript& script, const ScriptEvent& e) {
    std::cout << "viewer: script line " << e.line << ": " << e.command << " " << e.argument
              << (e.value.empty() ? "" : " " + e.value) << std::endl;
    if (e.command == "key")
        pressKey(state, catalog, window, keyNamed(e.argument));
    else if (e.command == "shader")
        selectShader(state, catalog, e.argument);
    else if (e.command == "variant") {
        const auto eq = e.argument.find('=');
        if (eq == std::string::npos) throw std::invalid_argument("variant wants AXIS=VALUE");
        auto picks = state.catalogue.picks;
        setAxis(picks, e.argument.substr(0, eq), e.argument.substr(eq + 1));
        const auto& c = state.catalogue;
        const std::string why = whyNotAVariant(*catalog::findShader(catalog, c.shader),
                                               render::featuresOf(c.lights, c.fog.has_value()), picks);
        if (!why.empty()) throw std::invalid_argument(why);
        pickAxis(state, e.argument.substr(0, eq), e.argument.substr(eq + 1));
    } else if (e.command == "scene") {
        if (e.argument == "none")
            closeScene(state);
        else
            openScene(state, script.resolve(e.argument));
    } else if (e.command == "set")
        setParameter(state, e.argument, e.value);
    else if (e.command == "expect")
        return e.argument;
    return {};
}

}  // namespace prism::viewer
