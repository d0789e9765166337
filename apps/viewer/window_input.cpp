#include "window_input.h"

#include "camera_controller.h"

#include "runner/lab_tables.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace pathlab::viewer {

std::string keyHelp() {
    return "h        this help\n"
           "f        fullscreen on/off\n"
           "drag     orbit the camera\n"
           "click    inspect the pixel's paths (no motion, or shift+click)\n"
           "WASD     move (arrow keys too)\n"
           "1-" +
           std::to_string(AllLabs.size()) + "      lab: " + labNames(", ") +
           "\n"
           "Tab      your code <-> reference solution\n"
           "+ / -    continueProb up / down (lab 4)\n"
           "[ / ]    maxDepth down / up (labs 1-3)\n"
           "v        view: image, difference, split, noise, efficiency\n"
           "t        warp test of the lab's lobe (lab 5): samples against density\n"
           "r        restart accumulation\n"
           "Space    screenshot (.exr linear + .png)\n"
           "c        print the camera as .ecs options\n"
           "Esc, q   quit";
}

WindowInput::WindowInput(GLFWwindow* window, ViewSettings& settings)
    : window_(window), settings_(settings) {}

KeyCommand WindowInput::onKey(int key, int action) {
    seen_ = true;
    if (action == GLFW_RELEASE) return KeyCommand::None;
    // Held movement keys repeat; every other key acts once per press.
    if (moveCamera(key) || action == GLFW_REPEAT) return KeyCommand::None;
    if (chooseLab(key) || changeParameter(key) || windowKey(key)) return KeyCommand::None;
    switch (key) {
    case GLFW_KEY_H: return KeyCommand::ToggleHelp;
    case GLFW_KEY_R: return KeyCommand::Restart;
    case GLFW_KEY_V: return KeyCommand::NextViewMode;
    case GLFW_KEY_SPACE: return KeyCommand::Screenshot;
    case GLFW_KEY_T: return KeyCommand::WarpTest;
    default: return KeyCommand::None;
    }
}

/// W, A, S, D and the arrow keys, in steps of the distance to the point looked at, so that
/// they feel the same in a scene of any size. Whether `key` was one.
bool WindowInput::moveCamera(int key) {
    const float step = 0.02f * length(settings_.camera.lookAt - settings_.camera.position);
    switch (key) {
    case GLFW_KEY_W:
    case GLFW_KEY_UP: settings_.camera = move(settings_.camera, step, 0); return true;
    case GLFW_KEY_S:
    case GLFW_KEY_DOWN: settings_.camera = move(settings_.camera, -step, 0); return true;
    case GLFW_KEY_A:
    case GLFW_KEY_LEFT: settings_.camera = move(settings_.camera, 0, -step); return true;
    case GLFW_KEY_D:
    case GLFW_KEY_RIGHT: settings_.camera = move(settings_.camera, 0, step); return true;
    default: return false;
    }
}

/// The number keys choose the labs, in the order of pathlab/lab_list.h.
bool WindowInput::chooseLab(int key) {
    if (key < GLFW_KEY_1 || key >= GLFW_KEY_1 + static_cast<int>(AllLabs.size())) return false;
    settings_.lab = AllLabs[static_cast<size_t>(key - GLFW_KEY_1)];
    return true;
}

/// Tab, + / - and [ / ]: the implementation and the lab's parameters, kept within the ranges
/// the labs are written for.
bool WindowInput::changeParameter(int key) {
    LabParameters& parameters = settings_.parameters;
    switch (key) {
    case GLFW_KEY_TAB: switchImplementation(); return true;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
        parameters.continueProb = std::min(0.95f, parameters.continueProb + 0.05f);
        return true;
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
        parameters.continueProb = std::max(0.05f, parameters.continueProb - 0.05f);
        return true;
    case GLFW_KEY_LEFT_BRACKET:
        parameters.maxDepth = std::max(0, parameters.maxDepth - 1);
        return true;
    case GLFW_KEY_RIGHT_BRACKET:
        parameters.maxDepth = std::min(64, parameters.maxDepth + 1);
        return true;
    default: return false;
    }
}

/// Esc and q close the window, f makes it fullscreen, c prints the camera for a scene file.
bool WindowInput::windowKey(int key) {
    switch (key) {
    case GLFW_KEY_ESCAPE:
    case GLFW_KEY_Q: glfwSetWindowShouldClose(window_, GLFW_TRUE); return true;
    case GLFW_KEY_F: toggleFullscreen(); return true;
    case GLFW_KEY_C:
        std::printf("%s\n", cameraAsOptions(settings_.camera).c_str());
        std::fflush(stdout);
        return true;
    default: return false;
    }
}

/// The student release has no reference solutions to switch to: Tab says so instead.
void WindowInput::switchImplementation() {
    if (!solution::available()) {
        std::printf("Tab: the reference solutions are not part of this build\n");
        std::fflush(stdout);
        return;
    }
    settings_.implementation = settings_.implementation == Implementation::Student
                                   ? Implementation::Solution
                                   : Implementation::Student;
}

void WindowInput::toggleFullscreen() {
    if (glfwGetWindowMonitor(window_)) {
        glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_,
                             windowedHeight_, 0);
        return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return;
    const GLFWvidmode* video = glfwGetVideoMode(monitor);
    glfwGetWindowPos(window_, &windowedX_, &windowedY_);
    glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
    glfwSetWindowMonitor(window_, monitor, 0, 0, video->width, video->height, video->refreshRate);
}

void WindowInput::onFramebufferSize(int width, int height) {
    seen_ = true;
    if (width > 0 && height > 0) settings_.width = width, settings_.height = height;
}

void WindowInput::onMouseButton(int button, int action, int mods) {
    seen_ = true;
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    if (action == GLFW_RELEASE) {
        if (pressed_ && (!moved_ || shift_)) clicked_ = pixelAt(pressX_, pressY_);
        pressed_ = dragging_ = false;
        return;
    }
    // A press on the panel moves the panel, not the camera, and inspects nothing.
    pressed_ = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
    shift_ = (mods & GLFW_MOD_SHIFT) != 0;
    dragging_ = pressed_ && !shift_;
    moved_ = false;
    glfwGetCursorPos(window_, &lastX_, &lastY_);
    pressX_ = lastX_, pressY_ = lastY_;
}

void WindowInput::onCursor(double x, double y) {
    seen_ = true;
    // A hand's click wanders a pixel or two: beyond that it is a drag, not a click. The camera
    // stays until then, so that a click does not restart the accumulation.
    if (pressed_ && std::abs(x - pressX_) + std::abs(y - pressY_) > 3) moved_ = true;
    if (!dragging_ || !moved_) return;
    settings_.camera = orbit(settings_.camera, static_cast<float>(x - lastX_) * 0.005f,
                             static_cast<float>(y - lastY_) * 0.005f);
    lastX_ = x, lastY_ = y;
}

/// The image's pixel under the cursor's window position (the framebuffer may be larger, HiDPI).
std::pair<int, int> WindowInput::pixelAt(double x, double y) const {
    int windowWidth = 1, windowHeight = 1;
    glfwGetWindowSize(window_, &windowWidth, &windowHeight);
    const double sx = static_cast<double>(settings_.width) / std::max(windowWidth, 1);
    const double sy = static_cast<double>(settings_.height) / std::max(windowHeight, 1);
    return {std::clamp(static_cast<int>(x * sx), 0, settings_.width - 1),
            std::clamp(static_cast<int>(y * sy), 0, settings_.height - 1)};
}

bool WindowInput::takeSeen() { return std::exchange(seen_, false); }

} // namespace pathlab::viewer
