#include "glfw_session.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl2.h>

#include <cstdlib>

namespace pathlab::viewer {

namespace {
std::string glfwProblem; ///< set by GLFW's error callback, which takes no user pointer
} // namespace

std::string missingDisplay() {
#if defined(__linux__) || defined(__FreeBSD__)
    // X11 or Wayland: with neither variable set there is no screen to open a window on, and
    // saying so is clearer than GLFW's error. (macOS and Windows always have their one screen;
    // there glfwInit says when it cannot be used, e.g. over ssh.)
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) return "DISPLAY is not set";
#endif
    return "";
}

GlfwSession::~GlfwSession() {
    if (imgui_) {
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwSession::open(int width, int height) {
    glfwSetErrorCallback([](int, const char* message) { glfwProblem = message; });
    if (!glfwInit()) return false;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
    // The window is sized in screen coordinates; on HiDPI screens the framebuffer, which is
    // what gets rendered, is larger.
    window_ = glfwCreateWindow(width, height, "PathLab", nullptr, nullptr);
    if (!window_) return false;
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);
    return true;
}

std::string GlfwSession::problem() { return glfwProblem; }

void GlfwSession::startImGui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // no imgui.ini littering the build folder
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL2_Init();
    imgui_ = true;
}

} // namespace pathlab::viewer
