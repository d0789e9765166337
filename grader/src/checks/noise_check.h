#pragma once
/// The noise check: a correct lab's per-sample variance on the rubric's noise scene, from its
/// correctness renders, against the reference solution's (grader/references/).

#include "checks/check_result.h"
#include "checks/grader_setup.h"

namespace pathlab::grader {

/// Per-sample variances on the noise scene, the lab's and the reference solution's (0: not
/// compared).
struct SampleVariances {
    double student = 0, solution = 0;
};

struct NoiseOutcome {
    CheckResult check;
    SampleVariances variances; ///< for the speed check's efficiency
};

/// `noise`: the variance checkCorrectness measured (-1: none); `correct`: its verdict.
NoiseOutcome checkNoise(const GraderSetup& setup, Lab lab, bool correct, double noise);

} // namespace pathlab::grader
