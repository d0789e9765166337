// Hostile submission: a fork bomb. Stopped by the sandbox: the submission viewer may not start
// processes (fork fails), and the run's time limit ends the loop.
#include "pathlab/lab.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static bool reported = false;
    for (;;) {
        if (::fork() < 0 && !reported) {
            std::fprintf(stderr, "fork bomb: fork failed: %s\n", std::strerror(errno));
            std::fflush(stderr);
            reported = true;
        }
    }
    (void)ray, (void)depth, (void)ctx;
    return Color();
}

} // namespace pathlab::branching
