#pragma once
/// A progress line with a bar, the share done, counts and the time left, on standard error: the
/// grader's renders and submissions, a headless render's samples.

#include <chrono>
#include <string>

namespace pathlab {

class ProgressBar {
public:
    /// `unit` names what is counted ("renders", "submissions", "samples").
    ProgressBar(std::string what, std::string unit);
    /// Redrawn in place on a terminal; in a log, a line at each quarter and at the end.
    void update(long long done, long long total, const std::string& note = "");

private:
    std::string what_, unit_;
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
};

} // namespace pathlab
