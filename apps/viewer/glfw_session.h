#pragma once
/// GLFW, the window with its OpenGL context, and Dear ImGui on it: set up in order, and
/// released whatever happens.

#include <string>

struct GLFWwindow;

namespace pathlab::viewer {

/// Why no window can open here ("DISPLAY is not set"), or "" where one may.
std::string missingDisplay();

class GlfwSession {
public:
    GlfwSession() = default;
    ~GlfwSession();
    GlfwSession(const GlfwSession&) = delete;
    GlfwSession& operator=(const GlfwSession&) = delete;

    /// glfwInit and a window of that size in screen coordinates, its OpenGL 2.1 context
    /// current; false, with GLFW's reason in problem(), if there is none.
    bool open(int width, int height);
    /// GLFW's last error, which it reports through a callback.
    static std::string problem();
    /// ImGui on the window; after the window's callbacks are set, since ImGui chains to them.
    void startImGui();
    GLFWwindow* window() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
    bool imgui_ = false;
};

} // namespace pathlab::viewer
