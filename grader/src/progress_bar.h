#pragma once
/// A progress line with counts and an estimate of the time left, on standard error.

#include <chrono>
#include <string>

namespace pathlab::grader {

class ProgressBar {
public:
    /// `unit` names what is counted ("renders", "submissions").
    ProgressBar(std::string what, std::string unit);
    /// Redrawn in place on a terminal; in a log, a line at each quarter and at the end.
    void update(int done, int total, const std::string& note = "");

private:
    std::string what_, unit_;
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
};

} // namespace pathlab::grader
