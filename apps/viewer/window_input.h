#pragma once
/// The keys, the mouse and the window's size, turned into the view settings they change (and
/// into what else a key asks of the window).

#include "runner/progressive_renderer.h"

#include <string>

struct GLFWwindow;

namespace pathlab::viewer {

/// What a key asks of the window beyond the settings and the window that WindowInput changes.
enum class KeyCommand { None, Restart, NextViewMode, Screenshot, ToggleHelp };

/// The keys, one a line, for the panel's help; the labs' from the list of labs.
std::string keyHelp();

class WindowInput {
public:
    /// Changes `settings`, which the window asks the renderer for.
    WindowInput(GLFWwindow* window, ViewSettings& settings);

    KeyCommand onKey(int key, int action);
    void onFramebufferSize(int width, int height);
    void onMouseButton(int button, int action);
    void onCursor(double x, double y);
    /// The window must be drawn again (uncovered, or input the panel may show).
    void onRefresh() { seen_ = true; }

    /// Whether input came since the last call: an unchanged frame is drawn again only then.
    bool takeSeen();

private:
    bool moveCamera(int key);
    bool chooseLab(int key);
    bool changeParameter(int key);
    bool windowKey(int key);
    void switchImplementation();
    void toggleFullscreen();

    GLFWwindow* window_;
    ViewSettings& settings_;
    bool seen_ = true; ///< the first loop draws the panel before any frame
    bool dragging_ = false;
    double lastX_ = 0, lastY_ = 0;
    /// Where the window was before fullscreen, to go back to.
    int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
};

} // namespace pathlab::viewer
