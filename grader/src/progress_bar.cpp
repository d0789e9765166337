#include "progress_bar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace pathlab::grader {

ProgressBar::ProgressBar(std::string what, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), start_(std::chrono::steady_clock::now()),
      terminal_(::isatty(STDERR_FILENO)) {}

void ProgressBar::update(int done, int total, const std::string& note) {
    const bool quarter = 4 * done / std::max(total, 1) != 4 * (done - 1) / std::max(total, 1);
    if (!terminal_ && done != total && !quarter) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int width = 30, filled = width * done / std::max(total, 1);
    std::fprintf(stderr, "%s%s [%s%s] %d/%d %s, ETA %.0f s%s%s%s", terminal_ ? "\r" : "",
                 what_.c_str(), std::string(filled, '=').c_str(),
                 std::string(width - filled, ' ').c_str(), done, total, unit_.c_str(),
                 done > 0 ? elapsed / done * (total - done) : 0.0, note.empty() ? "" : "  ",
                 note.c_str(), terminal_ ? "   " : "\n");
    if (terminal_ && done == total) std::fputc('\n', stderr);
    std::fflush(stderr);
}

} // namespace pathlab::grader
