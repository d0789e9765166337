#pragma once
/// The keys, the mouse and the window's size, turned into the view settings they change (and
/// into what else a key asks of the window).

#include "runner/progressive_renderer.h"

#include <optional>
#include <string>
#include <utility>

struct GLFWwindow;

namespace pathlab::viewer {

/// What a key asks of the window beyond the settings and the window that WindowInput changes.
enum class KeyCommand { None, Restart, NextViewMode, Screenshot, ToggleHelp, WarpTest };

/// The keys, one a line, for the panel's help; the labs' from the list of labs.
std::string keyHelp();

class WindowInput {
public:
    /// Changes `settings`, which the window asks the renderer for.
    WindowInput(GLFWwindow* window, ViewSettings& settings);

    KeyCommand onKey(int key, int action);
    void onFramebufferSize(int width, int height);
    /// A press and release without motion between them, or a shift+click, is a click on a
    /// pixel (takeClickedPixel); a drag without shift orbits the camera.
    void onMouseButton(int button, int action, int mods);
    void onCursor(double x, double y);
    /// The window must be drawn again (uncovered, or input the panel may show).
    void onRefresh() { seen_ = true; }

    /// Whether input came since the last call: an unchanged frame is drawn again only then.
    bool takeSeen();
    /// The pixel clicked since the last call, in the framebuffer's pixels (the image's).
    std::optional<std::pair<int, int>> takeClickedPixel() { return std::exchange(clicked_, {}); }

private:
    bool moveCamera(int key);
    bool chooseLab(int key);
    bool changeParameter(int key);
    bool windowKey(int key);
    void switchImplementation();
    void toggleFullscreen();
    std::pair<int, int> pixelAt(double x, double y) const;

    GLFWwindow* window_;
    ViewSettings& settings_;
    bool seen_ = true; ///< the first loop draws the panel before any frame
    bool dragging_ = false;
    double lastX_ = 0, lastY_ = 0;
    bool pressed_ = false, moved_ = false, shift_ = false; ///< the left button's press, for clicks
    double pressX_ = 0, pressY_ = 0;
    std::optional<std::pair<int, int>> clicked_;
    /// Where the window was before fullscreen, to go back to.
    int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
};

} // namespace pathlab::viewer
