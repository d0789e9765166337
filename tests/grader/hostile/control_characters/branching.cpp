// Hostile submission: on its first sample it prints, and then aborts, an escape sequence that
// would set a terminal's title, wipe the line above and write a green "6 / 6" over it, and a
// forged line of the batch's. What a lab printed reaches the feedback and the logs with every
// control byte written as \xNN: a terminal that shows grader.log shows the bytes, not their
// effect.
#include "pathlab/lab.h"

#include <cstdio>
#include <cstdlib>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    std::fputs("\r\x1b[2K\x1b[1A\x1b[2K\x1b]0;GRADER OK\x07\x1b[32mbranching   correctness   6 / 6"
               "\x1b[0m\nbatch: hostile graded 40 / 40, every check passed\n",
               stderr);
    std::abort();
    (void)ray, (void)depth, (void)ctx;
}

} // namespace pathlab::branching
