#pragma once
/// The speed check: a correct lab's timed renders, interleaved with the reference solution's,
/// judged by samples per CPU-second or by efficiency as the rubric says, and explained with both
/// labs' rays per sample. A timed run is the correctness render of the speed scene again,
/// argument for argument (correctness_renders.h), and must render the same images; its time is
/// the kernel's count of the sandbox's CPU time, which the machine's load changes little and the
/// lab cannot report itself. A lab fails only when its ratio lies below the threshold with
/// confidence (rubric: speed.alpha); pairs are added while that is undecided, up to a cap, where
/// the lab has the benefit of the doubt.

#include "checks/check_result.h"
#include "checks/grader_setup.h"
#include "checks/lab_measurement.h"
#include "checks/noise_check.h"
#include "isolation/render_run.h"
#include "isolation/start_up_times.h"

namespace pathlab::grader {

/// The most pairs a lab is timed with, in multiples of the rubric's speed.runs.
constexpr int SpeedPairsCap = 4;

/// Below this share of their cores, the timed runs' machine was busy, and the check says so.
constexpr double BusyShare = 0.8;

/// The verdict and the figures measured on the way (which LabGrade keeps).
struct SpeedOutcome : SpeedFigures {
    CheckResult check;
};

/// What the checks before it give the speed check.
struct SpeedInputs {
    SampleVariances variances; ///< the noise check's, for a lab judged by efficiency
    /// The correctness renders' images of the speed scene (CorrectnessOutcome), which the timed
    /// runs must render again.
    std::vector<std::vector<float>> speedSceneImages;
};

/// Times `lab` against the reference solution, as many pairs as the rubric's threshold needs.
TimedMeasurement timeLab(const GraderSetup& setup, Lab lab, const SpeedInputs& inputs,
                         StartUpTimes& startUps);

/// The verdict under `rubric`; `correct`: the correctness verdict (speed counts only then);
/// `variances`: the noise check's, for the efficiency.
SpeedOutcome judgeTimedRuns(const Rubric& rubric, Lab lab, bool correct,
                            const SampleVariances& variances, const TimedMeasurement& timed);

/// Speed in a build without the reference solutions: the student's timed runs alone, for the
/// ratios between labs; the check itself is the instructor's grader's.
SpeedOutcome timeWithoutSolutions(const GraderSetup& setup, Lab lab, bool correct,
                                  StartUpTimes& startUps);

/// The rubric's timed runs of one lab with `runner`'s labs alone (for the stored reference
/// figures): samples per CPU-second (the geometric mean; 0 if a run failed) and rays per sample.
struct TimedFigures {
    double samplesPerSecond = 0;
    RaysPerSample rays;
};
TimedFigures timedFigures(const GraderSetup& setup, const LabRunner& runner, Lab lab,
                          StartUpTimes& startUps);

} // namespace pathlab::grader
