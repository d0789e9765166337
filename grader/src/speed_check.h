#pragma once
/// The speed check: a correct lab's timed renders on the rubric's speed scene, interleaved with
/// the reference solution's, judged by samples/s or by efficiency as the rubric says, and
/// explained with both labs' rays per sample.

#include "grading.h"
#include "noise_check.h"

namespace pathlab::grader {

/// The verdict and the figures measured on the way (LabGrade's fields of the same names).
struct SpeedOutcome {
    CheckResult check;
    double studentSamplesPerSecond = 0, solutionSamplesPerSecond = 0; ///< the timed runs' medians
    RaysPerSample studentRays, solutionRays;
    double efficiencyRatio = 0; ///< 0: unknown
};

/// `correct`: the correctness verdict (speed counts only for a correct lab); `variances`: the
/// noise check's, for the efficiency; `startUps`: the grading's start-up measurements.
SpeedOutcome checkSpeed(const GraderSetup& setup, Lab lab, bool correct,
                        const SampleVariances& variances, StartUpTimes& startUps);

} // namespace pathlab::grader
