#pragma once
/// A headless render's progress line: a bar, the share done and the time left, redrawn in place
/// on a terminal.

#include "pathlab/render/render_progress.h"
#include "pathlab/support/ticking_thread.h"

#include <string>

namespace pathlab {

/// Draws the pass under way of `progress` (which must outlive it) on stderr from a thread of its
/// own, a few times a second, until destroyed. Only where stderr is a terminal: a pipe, a log,
/// the grader and CI get nothing. A render done within half a second draws nothing either.
class RenderProgressLine {
public:
    /// `what` starts the line, e.g. "render.png".
    RenderProgressLine(const RenderProgress& progress, std::string what);
    /// Draws the last state and ends the line, if any was drawn (thread_'s destructor).
    RenderProgressLine(const RenderProgressLine&) = delete;
    RenderProgressLine& operator=(const RenderProgressLine&) = delete;

private:
    void draw();

    const RenderProgress& progress_;
    const std::string what_;
    TickingThread thread_;
};

} // namespace pathlab
