#pragma once
/// CPU time: the measure of a render's work that other programs on the machine change little,
/// where its wall time grows with their load. The renderer sums its threads' CPU time over the
/// tiles they render (Renderer::cpuSeconds); the figures students compare use it.

#include <string>

namespace pathlab {

/// Which clock threadCpuSeconds() reads.
enum class CpuClock {
    PerThread, ///< the calling thread's own (Linux and macOS: CLOCK_THREAD_CPUTIME_ID; Windows:
               ///< GetThreadTimes)
    Process,   ///< the whole process's: where there is no per-thread clock, or where the
               ///< environment sets PATHLAB_CPU_CLOCK=process (the tests' way to the fallback)
};

/// The clock this platform (and environment) gives; decided once.
CpuClock cpuClock();

/// "per-thread", or the fallback in words: "process (no per-thread CPU clock here: ...)".
std::string cpuClockName();

/// Seconds of CPU time (user and system) used so far by the calling thread, or by the process
/// where cpuClock() is Process.
double threadCpuSeconds();

/// Seconds of CPU time used so far by every thread of the process.
double processCpuSeconds();

/// The smallest step of threadCpuSeconds(), in seconds (1 ns on Linux; 15.6 ms on Windows).
double cpuClockResolution();

} // namespace pathlab
