#pragma once
/// Runs another program with a time limit and resource limits, and says how it ended.

#include <cstddef>
#include <string>
#include <vector>

namespace pathlab::grader {

struct ProcessLimits {
    double wallSeconds = 60; ///< killed (with its whole process group) after this
    /// address-space limit per process (RLIMIT_AS); 0 = none, and none in a sanitized build
    long long memoryBytes = 4LL << 30;
    double cpuSeconds = 0;   ///< CPU time per process (RLIMIT_CPU); 0 = none
    long long fileBytes = 0; ///< largest file it may write (RLIMIT_FSIZE); 0 = none
    int processes = 0;       ///< processes of its user (RLIMIT_NPROC); 0 = none
};

/// How to start it, beyond its limits.
struct ProcessOptions {
    std::vector<int> cpus; ///< run only on these cores (empty: any; Linux only)
    int user = -1;         ///< run as this user id (needs root; -1: as we are)
    /// Give it a pipe as file descriptor 3 and keep what it writes there, up to this many
    /// bytes (0: no descriptor 3). The sandbox hands files back this way.
    size_t collectBytes = 0;
};

struct ProcessOutcome {
    bool started = false;
    bool timedOut = false;
    int exitStatus = -1;          ///< when it exited normally
    int signal = 0;               ///< when a signal ended it
    double seconds = 0;           ///< wall time, measured here
    double wallLimit = 0;         ///< the time limit it ran under (ProcessLimits::wallSeconds)
    std::string output;           ///< stdout and stderr together (the last 64 KiB)
    std::string collected;        ///< what it wrote on descriptor 3
    bool collectOverflow = false; ///< it wrote more there than allowed

    bool succeeded() const { return started && !timedOut && signal == 0 && exitStatus == 0; }
    /// One sentence a student can act on, e.g. "crashed (segmentation fault, signal 11)".
    std::string describe() const;
    /// The last lines it printed, for feedback (at most `lines` lines, each cut to 200 chars).
    std::string outputTail(int lines = 6) const;
};

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits,
                          const ProcessOptions& options = {});

} // namespace pathlab::grader
