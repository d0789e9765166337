#include "pathlab/support/cpu_clock.h"

#include <cstdlib>
#include <cstring>
#include <ctime>
#if defined(_WIN32)
#define NOMINMAX
#include <windows.h>
#endif

namespace pathlab {

namespace {

#if defined(_WIN32)
/// A FILETIME of 100 ns ticks, in seconds.
double seconds(const FILETIME& t) {
    return static_cast<double>((static_cast<unsigned long long>(t.dwHighDateTime) << 32) |
                               t.dwLowDateTime) *
           1e-7;
}
#else
double seconds(clockid_t clock) {
    timespec t{};
    if (::clock_gettime(clock, &t) != 0) return 0;
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
#endif

bool perThreadAvailable() {
    const char* asked = std::getenv("PATHLAB_CPU_CLOCK");
    if (asked && std::strcmp(asked, "process") == 0) return false;
#if defined(_WIN32)
    return true;
#elif defined(CLOCK_THREAD_CPUTIME_ID)
    timespec t{};
    return ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0;
#else
    return false;
#endif
}

} // namespace

CpuClock cpuClock() {
    static const CpuClock clock = perThreadAvailable() ? CpuClock::PerThread : CpuClock::Process;
    return clock;
}

std::string cpuClockName() {
    return cpuClock() == CpuClock::PerThread
               ? "per-thread"
               : "process (no per-thread CPU clock here: the whole process's CPU time, the "
                 "window's drawing and any thread of the lab's own included)";
}

double threadCpuSeconds() {
    if (cpuClock() == CpuClock::Process) return processCpuSeconds();
#if defined(_WIN32)
    FILETIME created, exited, kernel, user;
    if (!GetThreadTimes(GetCurrentThread(), &created, &exited, &kernel, &user)) return 0;
    return seconds(kernel) + seconds(user);
#elif defined(CLOCK_THREAD_CPUTIME_ID)
    return seconds(CLOCK_THREAD_CPUTIME_ID);
#else
    return processCpuSeconds();
#endif
}

double processCpuSeconds() {
#if defined(_WIN32)
    FILETIME created, exited, kernel, user;
    if (!GetProcessTimes(GetCurrentProcess(), &created, &exited, &kernel, &user)) return 0;
    return seconds(kernel) + seconds(user);
#else
    return seconds(CLOCK_PROCESS_CPUTIME_ID);
#endif
}

double cpuClockResolution() {
#if defined(_WIN32)
    return 0.015625; // the scheduler's tick, in which GetThreadTimes counts
#else
    timespec t{};
    const clockid_t clock =
        cpuClock() == CpuClock::PerThread ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID;
    if (::clock_getres(clock, &t) != 0) return 0.01;
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
#endif
}

} // namespace pathlab
