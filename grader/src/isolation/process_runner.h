#pragma once
/// Runs another program with a time limit and resource limits, and says how it ended.

#include "process/child_process.h"

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
    /// Its output is read up to this many bytes, then no more: what it prints after fails
    /// (ProcessOutcome::outputCutOff); 0 = all of it.
    size_t outputReadBytes = 0;
};

/// How to start it, beyond its limits.
struct ProcessOptions {
    std::vector<int> cpus; ///< run only on these cores (empty: any; Linux only)
    int user = -1;         ///< run as this user id (needs root; -1: as we are)
    /// Give it a pipe as file descriptor 3 and keep what it writes there, up to this many
    /// bytes (0: no descriptor 3). The sandbox hands files back this way.
    size_t collectBytes = 0;
    /// Open files it gets as descriptors 10, 11, ... (child_process.h, ChildSetup::passedFds).
    std::vector<int> passedFds;
    /// Nothing of this process but what is named reaches it (ChildSetup::isolated).
    bool isolated = false;
};

/// The run as process/ measured it (ChildRun: started, timed out, wall and CPU seconds, its
/// output, the last 64 KiB of stdout and stderr together, and what it wrote on descriptor 3),
/// with the limits it ran under and how it ended in the grader's terms.
struct ProcessOutcome : ChildRun {
    int exitStatus = -1;        ///< when it exited normally
    int signal = 0;             ///< when a signal ended it
    int stoppedBy = 0;          ///< the signal it stopped itself with (the sandbox then ends it)
    double wallLimit = 0;       ///< the time limit it ran under (ProcessLimits::wallSeconds)
    double cpuLimit = 0;        ///< the CPU time limit it ran under (0: none)
    size_t outputReadBytes = 0; ///< ProcessLimits::outputReadBytes, past which outputCutOff

    bool succeeded() const {
        return started && !timedOut && signal == 0 && stoppedBy == 0 && exitStatus == 0;
    }
    /// Whether the CPU time limit ended it.
    bool usedUpCpuTime() const;
    /// One sentence a student can act on, e.g. "crashed (segmentation fault, signal 11)".
    std::string describe() const;
    /// "it printed more than 4 MiB: what followed was not read", or "" if it printed less.
    std::string outputNote() const;
    /// The last lines it printed, for feedback (at most `lines` lines, each cut to 200 chars).
    std::string outputTail(int lines = 6) const;
};

ProcessOutcome runProcess(const std::vector<std::string>& argv, const ProcessLimits& limits,
                          const ProcessOptions& options = {});

} // namespace pathlab::grader
