#pragma once
/// Runs another program with a time limit and resource limits, and says how it ended.

#include <string>
#include <vector>

namespace pathlab::grader {

struct ProcessLimits {
    double wallSeconds = 60;          ///< killed (with its whole process group) after this
    long long memoryBytes = 4LL << 30; ///< address-space limit (RLIMIT_AS); 0 = none
};

struct ProcessOutcome {
    bool started = false;
    bool timedOut = false;
    int exitStatus = -1; ///< when it exited normally
    int signal = 0;      ///< when a signal ended it
    double seconds = 0;  ///< wall time, measured here
    std::string output;  ///< stdout and stderr together (the last 64 KiB)

    bool succeeded() const { return started && !timedOut && signal == 0 && exitStatus == 0; }
    /// One sentence a student can act on, e.g. "crashed (segmentation fault, signal 11)".
    std::string describe() const;
};

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits);

} // namespace pathlab::grader
