#pragma once
/// The kit's own cost of a ray on this machine: CPU time per ray of a path tracer that is the
/// kit's, not a lab's (diffuse bounces, next-event estimation at every hit), rendered by the same
/// renderer as the labs. Where the reference solutions cannot be timed beside a student's lab
/// (the student release), it carries their stored samples per CPU-second from the machine they
/// were measured on to this one: a lab costs about the same multiple of it on any machine.

#include <string>

namespace pathlab::grader {

/// The CPU seconds per ray of the kit's path tracer on the scene of `ecsFile` at `width` x
/// `height`, with `threads` threads (0: all cores): the whole process's CPU time, as the timed
/// runs count it, over a few renders of a few tenths of a second each, the median. Throws
/// InputError when the scene does not load.
double kitCpuSecondsPerRay(const std::string& ecsFile, int width, int height, int threads);

} // namespace pathlab::grader
