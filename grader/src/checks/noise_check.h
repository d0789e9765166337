#pragma once
/// The noise check: a correct lab's per-sample variance on the rubric's noise scene, from its
/// correctness renders, against the reference solution's (grader/references/).

#include "checks/check_result.h"
#include "checks/grader_setup.h"
#include "checks/lab_measurement.h"

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

/// The figures: `noise`, the variance checkCorrectness measured (-1: none), beside the
/// reference solution's on the rubric's noise scene.
NoiseMeasurement measureNoise(const GraderSetup& setup, Lab lab, double noise);

/// The verdict under `rubric`; `correct`: the correctness verdict (noise counts only then).
NoiseOutcome judgeNoise(const Rubric& rubric, Lab lab, bool correct, const NoiseMeasurement& m);

} // namespace pathlab::grader
