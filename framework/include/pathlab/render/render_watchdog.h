#pragma once
/// Ends a render whose lab stopped finishing samples, with a line that names the lab and the
/// likely cause, instead of letting it run on in silence.

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/render_progress.h"
#include "pathlab/support/ticking_thread.h"

#include <functional>
#include <string>

namespace pathlab {

/// The lab a watched render runs, and whose code it is.
struct WatchedLab {
    Lab lab;
    Implementation implementation;
};

/// Watches a renderer's progress from a thread of its own. A lab caught in an endless loop (or a
/// recursion that never ends) never returns to the renderer, whose thread can then be neither
/// stopped nor joined: so once a pass has finished no sample for `seconds`, the watchdog prints
/// one line on stderr (stuckMessage) and ends the process with status 1 at once, without
/// destructors. It stands down while a debugger is attached, where a breakpoint stops samples
/// as well.
class RenderWatchdog {
public:
    /// A correct lab finishes a packet of samples in milliseconds, even at the largest spp
    /// anyone uses and under the sanitizers: a minute is generous.
    static constexpr double DefaultSeconds = 60;

    /// Watches `progress` (which must outlive the watchdog); `seconds` = 0 watches nothing.
    /// `watchedLab` says, when it fires, which lab the stuck pass runs: it is called on the
    /// watchdog's thread. With `fromStart`, the time before the first pass begins counts too (a
    /// headless render, whose lab's code loads just before: a static initializer of the lab that
    /// never returns is caught as an endless loop is); without, only passes are watched (a
    /// window idles between them).
    RenderWatchdog(const RenderProgress& progress, double seconds,
                   std::function<WatchedLab()> watchedLab, bool fromStart = false);
    RenderWatchdog(const RenderWatchdog&) = delete;
    RenderWatchdog& operator=(const RenderWatchdog&) = delete;

    /// The line it prints: the lab, its file, how long it was stuck, where to look, and how to
    /// change the wait.
    static std::string stuckMessage(const WatchedLab& watched, double seconds);

private:
    void watch();

    const RenderProgress& progress_;
    const double seconds_;
    const bool fromStart_;
    const std::function<WatchedLab()> watchedLab_;
    TickingThread thread_;
};

} // namespace pathlab
