#pragma once
/// The options of the interactive window, read beside the shared ones
/// (pathlab/render/render_options.h).

#include "view_mode.h"

#include "pathlab/render/render_options.h"

#include <optional>
#include <string>

namespace pathlab::viewer {

struct WindowOptions {
    int sppPerFrame = 1;          ///< --spp-per-frame
    bool printFrameRate = false;  ///< --print-frame-rate
    int frames = 0;               ///< --frames: quit after this many (0 = run until closed)
    std::string screenshot;       ///< --screenshot: save after --frames, then quit
    std::string windowCapture;    ///< --capture-window: the window as shown, panel included
    std::string referenceImage;   ///< --reference: image for the difference view
    std::optional<ViewMode> view; ///< --view: the mode shown first (then v as usual)
    bool inspectInWindow = false; ///< --inspect-window: --inspect X Y in the window, not headless
    bool warpPanel = false;       ///< --warp-panel: open with the lab's warp test shown (t)
};

/// The readers of the window's options, into `window`, for parseRenderOptions.
ExtraOptions windowOptionReaders(WindowOptions& window);

/// What the options mean together: a screenshot or capture without --frames comes after 16.
/// Throws InputError for a --view this run cannot show (difference without --reference, split
/// without the reference solutions).
void completeWindowOptions(WindowOptions& window);

/// Throws InputError for an --inspect-window the run cannot honour: without --inspect X Y, or
/// with -o or --inspect-out, which are headless.
void checkInspectWindow(const WindowOptions& window, const RenderOptions& options);

/// The summary of the window's options, for --help.
const char* windowOptionsHelp();

} // namespace pathlab::viewer
