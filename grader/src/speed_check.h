#pragma once
/// The speed check: a correct lab's timed renders on the rubric's speed scene, interleaved with
/// the reference solution's, judged by samples/s or by efficiency as the rubric says, and
/// explained with both labs' rays per sample.

#include "grading.h"

namespace pathlab::grader {

/// `correct`: the correctness verdict (speed counts only for a correct lab). Reads the noise
/// check's variances from `grade` for the efficiency; sets the figures in `grade`.
CheckResult checkSpeed(const GraderSetup& setup, Lab lab, bool correct, LabGrade& grade);

} // namespace pathlab::grader
