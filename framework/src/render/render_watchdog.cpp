#include "pathlab/render/render_watchdog.h"

#include "pathlab/support/this_process.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace pathlab {

RenderWatchdog::RenderWatchdog(const RenderProgress& progress, double seconds,
                               std::function<WatchedLab()> watchedLab, bool fromStart)
    : progress_(progress), seconds_(seconds), fromStart_(fromStart),
      watchedLab_(std::move(watchedLab)) {
    if (seconds_ > 0) thread_.start([this] { watch(); });
}

std::string RenderWatchdog::stuckMessage(const WatchedLab& watched, double seconds) {
    const std::string name(labName(watched.lab));
    const std::string file =
        (watched.implementation == Implementation::Student ? "labs/" : "solutions/") +
        labFileName(watched.lab);
    const char* limit = isDepthLimited(watched.lab) ? "its depth limit (ctx.maxDepth)"
                                                    : "its Russian roulette (ctx.continueProb)";
    char wait[32];
    std::snprintf(wait, sizeof wait, "%g", seconds);
    return "render watchdog: lab " + std::to_string(labNumber(watched.lab)) + " (" + name + ", " +
           file + ") has finished no sample for " + wait +
           " s: an endless loop, or recursion that never ends? Look in " + file +
           " for a while loop whose condition never changes, or a recursion without " + limit +
           ". (The viewer's --watchdog SECONDS sets this wait, 0 turns it off.)";
}

void RenderWatchdog::watch() {
    // Stillness is counted in the watchdog's own ticks, not by the clock: a process stopped
    // (Ctrl-Z, a debugger's breakpoint) and resumed has lost one tick, not the whole pause.
    const double tick = std::min(1.0, seconds_ / 4);
    const auto tickDuration = std::chrono::duration<double>(tick);
    uint64_t lastCount = progress_.samplesFinished();
    double stillFor = 0;
    while (thread_.sleep(tickDuration)) {
        const uint64_t count = progress_.samplesFinished();
        const bool watched = progress_.passRunning() || (fromStart_ && count == 0);
        if (count != lastCount || !watched) {
            lastCount = count;
            stillFor = 0;
            continue;
        }
        stillFor += tick;
        if (stillFor < seconds_) continue;
        if (debuggerAttached()) {
            stillFor = 0;
            continue;
        }
        // The stuck thread holds no lock of ours and cannot be joined: say why, and end here.
        const std::string line = "\n" + stuckMessage(watchedLab_(), seconds_) + "\n";
        // A line redrawn in place (the progress line) is ended first; a log gets the line alone.
        std::fputs(standardErrorIsTerminal() ? line.c_str() : line.c_str() + 1, stderr);
        std::fflush(stderr);
        std::_Exit(1);
    }
}

} // namespace pathlab
