#pragma once
/// What the checks of one lab return: each check's verdict (CheckResult) and the lab's grade made
/// of them (LabGrade), which the reports print. The checks' input is grader_setup.h.

#include "checks/check_kind.h"
#include "checks/rays_per_sample.h"

#include "pathlab/render/lab_registry.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// How a hidden scene's verdict reads in CheckResult::hiddenSceneDetails, after its name: the
/// Gradescope report tells a failed one by it.
constexpr const char* HiddenSceneMatches = ": matches its reference";
constexpr const char* HiddenSceneDiffers = ": differs from its reference";

struct CheckResult {
    CheckKind kind = CheckKind::Correctness;
    double score = 0, maxScore = 0;
    bool passed = false;
    std::string summary;              ///< one line
    std::vector<std::string> details; ///< what to look at, in words
    std::string diagnosis;            ///< a failure's cause in a few words, for a class's summary
    /// Pass or fail per hidden scene, without its name (in every report; in Gradescope's, a test
    /// of its own with the visibility the rubric gives hidden scenes).
    std::vector<std::string> hiddenSceneDetails;
    /// False for a check this build cannot make (speed, without the reference solutions to time
    /// against): the instructor's grader makes it, and its points are not in this build's totals.
    bool gradedHere = true;
    /// For a check not graded here: this build's own figures say the instructor's grader would
    /// likely fail it (the speed of a lab that traces rays its estimator does not), and why is
    /// in the summary.
    bool atRisk = false;

    /// The check's name in every report (check_kind.h).
    std::string name() const { return std::string(checkName(kind)); }
};

/// What the speed check measured on the way to its verdict.
struct SpeedFigures {
    /// Per CPU-second: the geometric means of each side's timed runs, whose quotient is the ratio.
    double studentSamplesPerSecond = 0, solutionSamplesPerSecond = 0;
    RaysPerSample studentRays, solutionRays; ///< in the timed runs (the labs' own counts)
    /// 1/(variance x time per sample), yours ÷ the reference's; 0: unknown
    double efficiencyRatio = 0;
};

/// One lab's grade: its checks, and the figures of its speed check (SpeedFigures) and noise.
struct LabGrade : SpeedFigures {
    Lab lab = Lab::Branching;
    std::vector<CheckResult> checks;
    double studentVariance = 0, solutionVariance = 0; ///< per sample, on the noise scene
    bool rendersFinished = true; ///< false when a correctness render crashed, hung or ran out
    /// For the HTML report: per scene, the student's mean image, the reference and a heat map.
    struct Pictures {
        std::string scene;
        int width = 0, height = 0;
        std::vector<float> student, reference;
        /// The correctness check's t statistics of this scene and their two-sided p-values,
        /// [region][channel] as regionMeans lays them out (region 0 the whole image, then the
        /// tiles row by row), and the tiles per side: the HTML report's map of the tiles'
        /// z-scores.
        std::vector<double> regionT, regionP;
        int tilesPerSide = 0;
    };
    std::vector<Pictures> pictures;

    double score() const;
    double maxScore() const; ///< of the checks graded here
    double pointsNotGradedHere() const;
    double pointsAtRisk() const; ///< of the checks not graded here, those at risk
};

} // namespace pathlab::grader
