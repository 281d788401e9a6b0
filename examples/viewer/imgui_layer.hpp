// Dear ImGui on the viewer's GLFW window (Debian's libimgui-dev ships the GLFW and
// OpenGL3 backends compiled into libimgui.a). No imgui.ini is written.
//
//     ImGuiLayer ui(window);        // after any glfwSet*Callback: ImGui chains to them
//     ui.begin();  ... ImGui::Begin ... ;  ui.end();   // end() draws into the bound framebuffer
#pragma once

struct GLFWwindow;

namespace prism::viewer {

class ImGuiLayer {
  public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
    void begin();
    void end();
    static bool wantsKeyboard();
};

}  // namespace prism::viewer
