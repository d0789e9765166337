#pragma once
/// Whether other programs shared the machine while the benchmark timed something: the CPU time
/// its threads had against the wall time they took. The CPU-time figures change little with
/// that; the wall-clock ones slow down.

#include <string>
#include <vector>

namespace pathlab::bench {

/// What one timed measurement's threads had of the machine.
struct CpuUse {
    std::string what; ///< e.g. "roulette's passes on 2 threads"
    double cpuSeconds = 0, seconds = 0;
    int threads = 0;

    /// CPU time over wall time × the cores its threads could use (no more than the machine's):
    /// 1 when they ran all the time.
    double share() const;
};

/// "the machine was busy: ... had 45% of 2 cores (...); ..." of the measurement with the least
/// share, when that is well below all of it; "" when none is, or every one was too short to
/// tell.
std::string busyNote(const std::vector<CpuUse>& measurements);

/// "1 thread", "2 threads".
std::string threadsText(int threads);

} // namespace pathlab::bench
