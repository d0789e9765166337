// Hostile submission: signals every process it may, hoping to stop the grader or the other
// submissions' gradings. In the sandbox it sees only its own process and the sandbox's first,
// which no signal from inside reaches: it kills nothing, and renders black.
#include "pathlab/lab.h"

#include <csignal>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    ::kill(-1, SIGKILL);
    (void)ray, (void)depth, (void)ctx;
    return Color();
}

} // namespace pathlab::branching
