#pragma once
/// The panel over the image: the figures a student writes down, and the keys on request (h).

#include "pathlab/images/false_colour.h"
#include "view_mode.h"

#include <functional>
#include <optional>

namespace pathlab {
struct Frame;
struct ViewSettings;
} // namespace pathlab

namespace pathlab::viewer {

class ViewerPanel {
public:
    void toggleHelp() { showHelp_ = !showHelp_; }
    /// Other windows drawn in the same ImGui frame (the path inspector's).
    void alsoDraw(std::function<void()> windows) { otherWindows_ = std::move(windows); }

    /// Draws the panel with ImGui over what is drawn. The lab and its parameters are those of
    /// `settings`, asked for, so that a key shows at once; the figures are those of `frame`.
    /// With a `mapScale` (the noise and efficiency views), a scale bar of it too. `moreWindows`
    /// draws the window's other ImGui windows in the same ImGui frame.
    void draw(const Frame& frame, const ViewSettings& settings, ViewMode mode,
              float medianDifference, const std::optional<LogScale>& mapScale,
              const std::function<void()>& moreWindows = {});

private:
    bool showHelp_ = false; ///< the keys' window, which its own close button also hides
    std::function<void()> otherWindows_;
};

} // namespace pathlab::viewer
