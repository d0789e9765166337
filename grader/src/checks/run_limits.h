#pragma once
/// The limits every render of a grading runs under.

#include "checks/grader_setup.h"

namespace pathlab::grader {

/// Each render's limits: the rubric's, its time limit scaled to this machine (time_limit.h).
ProcessLimits limitsOf(const GraderSetup& setup);

} // namespace pathlab::grader
