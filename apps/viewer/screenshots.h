#pragma once
/// The window's pictures saved: the frame's image (Space, --screenshot) and the window as shown
/// (--capture-window).

#include <string>

namespace pathlab {
struct Frame;
}

namespace pathlab::viewer {

/// The frame's linear image to `requested`, or, with "" (Space), to .exr and .png files named
/// by its lab, implementation and spp; nothing before the first frame. False, said on stderr,
/// if a file could not be written.
bool saveScreenshot(const Frame& frame, const std::string& requested);

/// The back buffer, panel included, as `path` (call before the swap). False, said on stderr,
/// if it could not be written.
bool captureWindow(const std::string& path, int width, int height);

} // namespace pathlab::viewer
