// Hostile submission: widens its CPU set from the core it was given to every core, so that its
// timed runs get more than the reference's, or disturb another student's. The sandbox's filter
// refuses sched_setaffinity.
#include "pathlab/lab.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sched.h>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    cpu_set_t every;
    CPU_ZERO(&every);
    for (int cpu = 0; cpu < 64; ++cpu) CPU_SET(cpu, &every);
    const int widened = ::sched_setaffinity(0, sizeof every, &every);
    std::printf("sched_setaffinity: %s\n", widened == 0 ? "WIDENED" : std::strerror(errno));
    std::fflush(stdout);
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
