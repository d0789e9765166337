#include "pathlab/support/progress_bar.h"

#include "pathlab/support/this_process.h"

#include <algorithm>
#include <cstdio>

namespace pathlab {

ProgressBar::ProgressBar(std::string what, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()),
      terminal_(standardErrorIsTerminal()) {}

void ProgressBar::update(long long done, long long total, const std::string& note) {
    const long long whole = std::max(total, 1LL);
    const bool quarter = 4 * done / whole != 4 * (done - 1) / whole;
    if (!terminal_ && done != total && !quarter) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // A caller whose count of steps is off must not make the bar's fill negative.
    const int width = 30;
    const int filled =
        static_cast<int>(std::clamp(width * done / whole, 0LL, static_cast<long long>(width)));
    std::fprintf(
        stderr, "%s%s [%s%s] %3lld%% %lld/%lld %s, ETA %.0f s%s%s%s", terminal_ ? "\r" : "",
        what_.c_str(), std::string(filled, '=').c_str(), std::string(width - filled, ' ').c_str(),
        100 * done / whole, done, total, unit_.c_str(),
        done > 0 ? elapsed / static_cast<double>(done) * static_cast<double>(total - done) : 0.0,
        note.empty() ? "" : "  ", note.c_str(), terminal_ ? "   " : "\n");
    if (terminal_ && done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
}

} // namespace pathlab
