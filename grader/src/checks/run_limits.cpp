#include "checks/run_limits.h"

namespace pathlab::grader {

ProcessLimits limitsOf(const GraderSetup& setup) {
    return {setup.runSeconds > 0 ? setup.runSeconds : setup.rubric.secondsPerRun,
            setup.rubric.memoryBytes};
}

} // namespace pathlab::grader
