#include "checks/run_limits.h"

namespace pathlab::grader {

RenderLimits renderLimits(const Rubric& rubric, double scale) {
    const double seconds = rubric.secondsPerRun * scale;
    return {seconds, seconds / 2, seconds * WallLimitFactor, rubric.memoryBytes};
}

RenderLimits limitsOf(const GraderSetup& setup) { return renderLimits(setup.rubric); }

} // namespace pathlab::grader
