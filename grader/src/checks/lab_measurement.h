#pragma once
/// What grading one lab measured, apart from the rubric's points and thresholds. The checks'
/// verdicts are judged from it (judgeLab): when the lab is graded, and again, rendering nothing,
/// when a batch's rubric changed only points or thresholds (its re-score). A submission's are
/// stored beside its result as measurements.json, its pictures' images as .pfm files.

#include "checks/check_result.h"
#include "checks/rubric.h"
#include "checks/strategy_tiles.h"

#include "pathlab/render/ray_counters.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pathlab::grader {

/// The noise check's figures (noise_check.h).
struct NoiseMeasurement {
    double student = -1; ///< the lab's per-sample variance on the noise scene; -1: not measured
    double solution = 0; ///< the reference solution's, from the scene's reference
    std::string scene;
    /// Lab 6's per-tile variances against each strategy alone (strategy_noise.h); empty for
    /// the other labs, and for a lab 6 that failed correctness.
    StrategyTiles strategies;
};

/// The speed check's timed runs (speed_check.h), or why there are none.
struct TimedMeasurement {
    /// Why not timed, as the check's summary and diagnosis say it; both "" when timed.
    std::string notTimed, notTimedDiagnosis;
    std::vector<double> student, solution; ///< samples per CPU-second of each run, pair by pair
    /// The same runs' wall-clock seconds, which the verdict does not use: kept to show how much
    /// more wall time than CPU time varies on a busy machine.
    std::vector<double> studentWall, solutionWall;
    RayCounters studentRays, solutionRays;
    double studentSamples = 0, solutionSamples = 0;
    double cpuSeconds = 0, wallSeconds = 0; ///< over every run: how much of its cores it had
    int timingCores = 0;                    ///< the cores the runs were pinned to (0: any)
    bool imagesDiffer = false; ///< a timed run of the lab rendered other images than its seeds'

    bool timed() const { return notTimed.empty() && !student.empty(); }
};

/// Where the time of one lab's grading went, in wall-clock seconds (batch.log, summary.html).
struct PhaseSeconds {
    double correctness = 0; ///< the correctness renders, their retry and the reproducibility check
    double race = 0;        ///< the race check: compiling with ThreadSanitizer and its render
    double speed = 0;       ///< the timed series, waiting for the timing core included
};

struct LabMeasurement {
    Lab lab = Lab::Branching;
    PhaseSeconds seconds; ///< not judged: where the time went
    /// A lab not graded at all: why ("not submitted", "does not compile", ...) and the details.
    std::string ungraded;
    std::vector<std::string> ungradedDetails;
    /// The correctness check as it was judged: its verdict depends on no point and no threshold
    /// of the rubric's (alpha, seeds and scenes are measurement settings); only its score does.
    CheckResult correctness;
    bool rendersFinished = true;
    NoiseMeasurement noise;
    bool speedMeasured = false; ///< the grading measured speed (not --no-speed)
    TimedMeasurement speed;
    std::vector<LabGrade::Pictures> pictures;
};

/// The lab's grade under `rubric`: the checks' verdicts and scores from `m`.
LabGrade judgeLab(const Rubric& rubric, const LabMeasurement& m);

/// A lab that could not be graded at all (not submitted, does not compile): every check fails
/// with `reason` as its summary and diagnosis.
LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details);

/// measurements.json's entry for `m`; each picture's lab image is written to
/// FOLDER/pictures/LAB.SCENE.pfm (the reference's image is the scene's stored reference).
nlohmann::json measurementJson(const LabMeasurement& m, const std::string& folder);
/// The entry read back, the pictures' reference images left empty for the caller to fill.
/// Throws InputError on a malformed entry.
LabMeasurement readMeasurement(const nlohmann::json& j, const std::string& folder);

} // namespace pathlab::grader
