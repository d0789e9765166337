#include "pathlab/render/render_progress_line.h"

#include "pathlab/support/progress_bar.h"
#include "pathlab/support/this_process.h"

#include <chrono>
#include <cstdio>

namespace pathlab {

RenderProgressLine::RenderProgressLine(const RenderProgress& progress, std::string what)
    : progress_(progress), what_(std::move(what)) {
    if (standardErrorIsTerminal()) thread_ = std::thread([this] { draw(); });
}

RenderProgressLine::~RenderProgressLine() {
    if (!thread_.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
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
    std::unique_lock<std::mutex> lock(mutex_);
    if (wake_.wait_for(lock, 500ms, [this] { return stopping_; })) return;
    bool ended = false;
    while (!ended && !wake_.wait_for(lock, 250ms, [this] { return stopping_; })) ended = show();
    // Stopped before a full bar was drawn: the last state, and the line ended even if the pass
    // failed part way.
    if (!ended && !show()) std::fputc('\n', stderr);
}

} // namespace pathlab
