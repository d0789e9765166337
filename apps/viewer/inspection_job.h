#pragma once
/// The window's path inspector, off the UI thread: a clicked pixel's replay (runner/pixel_replay.h)
/// runs on a worker thread of its own, beside the render thread, so that the window keeps drawing
/// while it runs. A click while one runs replaces the one waiting: the last click is shown.

#include "runner/pixel_replay.h"
#include "runner/progressive_renderer.h"

#include "pathlab/render/render_options.h"

#include <future>
#include <optional>
#include <string>

namespace pathlab {
class RenderScene;
}

namespace pathlab::viewer {

/// A pixel's replay as the window shows it: the settings it was made with, and its result or
/// why there is none.
struct WindowInspection {
    ViewSettings settings;
    int x = 0, y = 0;
    PixelReplay replay;
    std::string error; ///< set when the replay threw; `replay` is then empty
};

class InspectionJob {
public:
    /// `options` gives what the window's settings do not (the sample count, the watchdog).
    InspectionJob(const RenderOptions& options, const RenderScene& scene);
    ~InspectionJob();
    InspectionJob(const InspectionJob&) = delete;
    InspectionJob& operator=(const InspectionJob&) = delete;

    /// Replays pixel (x, y) of an image made with `settings`: at once when no replay runs,
    /// otherwise after the running one (replacing any request still waiting).
    void request(const ViewSettings& settings, int x, int y);
    /// A finished replay, once (none while it runs); starts the waiting request, if any.
    std::optional<WindowInspection> takeFinished();
    /// A replay runs or waits.
    bool busy() const { return running_.valid() || waiting_.has_value(); }

private:
    struct Request {
        ViewSettings settings;
        int x = 0, y = 0;
    };
    void start(const Request& request);

    const RenderOptions& options_;
    const RenderScene& scene_;
    std::future<WindowInspection> running_;
    std::optional<Request> waiting_;
};

} // namespace pathlab::viewer
