#pragma once
/// The speed check: a correct lab's timed renders on the rubric's speed scene, interleaved with
/// the reference solution's, judged by samples/s or by efficiency as the rubric says, and
/// explained with both labs' rays per sample.

#include "checks/check_result.h"
#include "checks/grader_setup.h"
#include "checks/noise_check.h"
#include "isolation/render_run.h"
#include "isolation/start_up_times.h"

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

/// The start-up of one render on the rubric's speed scene with `runner`'s labs (one pixel:
/// loading the scene and building Embree's BVH), the median of three, measured once per grading
/// (in `startUps`); 0 if none ran. The speed check subtracts it; time_limit.h scales the limits
/// with it.
double speedSceneStartUpSeconds(const GraderSetup& setup, const LabRunner& runner,
                                StartUpTimes& startUps);

/// The median samples/s of the rubric's timed runs of one lab with `runner`'s labs alone (for
/// the stored reference figures); 0 if a run failed.
double timedSamplesPerSecond(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                             StartUpTimes& startUps);

} // namespace pathlab::grader
