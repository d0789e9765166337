// Hostile submission: stops its own process (SIGSTOP), as a debugger's breakpoint would, so
// that the sandbox waits for the time limit and the feedback blames an endless loop. The
// sandbox's first process sees it stop, ends it and says what it did.
#include "pathlab/lab.h"

#include <csignal>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    std::raise(SIGSTOP);
    (void)ray, (void)depth, (void)ctx;
    return Color();
}

} // namespace pathlab::branching
