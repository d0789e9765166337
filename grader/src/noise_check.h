#pragma once
/// The noise check: a correct lab's per-sample variance on the rubric's noise scene, from its
/// correctness renders, against the reference solution's (grader/references/).

#include "grading.h"

namespace pathlab::grader {

/// `noise`: the variance checkCorrectness measured (-1: none); `correct`: its verdict. Sets the
/// variances in `grade` for the speed check's efficiency.
CheckResult checkNoise(const GraderSetup& setup, Lab lab, bool correct, double noise,
                       LabGrade& grade);

} // namespace pathlab::grader
