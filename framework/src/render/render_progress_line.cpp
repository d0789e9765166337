#include "pathlab/render/render_progress_line.h"

#include "pathlab/support/progress_bar.h"
#include "pathlab/support/this_process.h"

#include <chrono>
#include <cstdio>

namespace pathlab {

RenderProgressLine::RenderProgressLine(const RenderProgress& progress, std::string what)
    : progress_(progress), what_(std::move(what)) {
    if (standardErrorIsTerminal()) thread_.start([this] { draw(); });
}

void RenderProgressLine::draw() {
    using namespace std::chrono_literals;
    ProgressBar bar(what_, "samples");
    const auto show = [&] {
        const auto total = static_cast<long long>(progress_.passSamples());
        const auto done = static_cast<long long>(progress_.passSamplesFinished());
        bar.update(done, total);
        return done == total; // the bar then ended its line
    };
    if (!thread_.sleep(500ms)) return;
    bool ended = false;
    while (!ended && thread_.sleep(250ms)) ended = show();
    // Stopped before a full bar was drawn: the last state, and the line ended even if the pass
    // failed part way.
    if (!ended && !show()) std::fputc('\n', stderr);
}

} // namespace pathlab
