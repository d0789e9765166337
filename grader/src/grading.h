#pragma once
/// The three checks of one lab: correctness, noise, frame rate.

#include "check_kind.h"
#include "diagnosis.h"
#include "expectation.h"
#include "race_report.h"
#include "rays_per_sample.h"
#include "render_run.h"
#include "rubric.h"
#include "start_up_times.h"

#include "pathlab/lab_parameters.h"

#include <functional>
#include <optional>
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

    /// The check's name in every report (check_kind.h).
    std::string name() const { return std::string(checkName(kind)); }
};

struct LabGrade {
    Lab lab = Lab::Branching;
    std::vector<CheckResult> checks;
    double studentSamplesPerSecond = 0, solutionSamplesPerSecond = 0; ///< the timed runs' medians
    double studentVariance = 0, solutionVariance = 0; ///< per sample, on the noise scene
    RaysPerSample studentRays, solutionRays;          ///< in the timed runs (the labs' own counts)
    double efficiencyRatio =
        0; ///< 1/(variance x time per sample), yours ÷ the reference's; 0: unknown
    bool rendersFinished = true; ///< false when a correctness render crashed, hung or ran out
    /// For the HTML report: per scene, the student's mean image, the reference and a heat map.
    struct Pictures {
        std::string scene;
        int width = 0, height = 0;
        std::vector<float> student, reference;
    };
    std::vector<Pictures> pictures;

    double score() const;
    double maxScore() const; ///< of the checks graded here
    double pointsNotGradedHere() const;
};

/// A scene to grade on: its .ecs path and what it is compared with.
struct GradingScene {
    std::string path;
    SceneReference reference;
    std::optional<FurnaceModel> furnace; ///< a furnace's analytic values, for the diagnosis
    /// Rendered at these instead of the rubric's parameters (the parameter check).
    std::optional<LabParameters> parameters;
    /// What feedback calls it: the scene's name, or "hidden scene N" for one of the instructor's
    /// hidden scenes, of which feedback says pass or fail and a likely cause, never the name,
    /// the images or the tiles (unless the instructor reveals them).
    std::string name;
    bool hidden = false;
};

/// How the frame-rate check keeps its timings fair on a machine that does other work meanwhile
/// (grader batch): the timed runs take cores of their own, one grading at a time.
struct TimingPolicy {
    std::vector<int> cpus; ///< the timed runs' cores (empty: wherever the runners run)
    std::string lockFile;  ///< held for a lab's whole interleaved series (empty: no lock)
    int threads = 0;       ///< threads per timed render (0: as the other renders)
};

struct GraderSetup {
    LabRunner student;  ///< runs the labs being graded
    LabRunner solution; ///< runs the reference solutions
    TimingPolicy timing;
    Rubric rubric;
    std::vector<GradingScene> scenes;
    std::string scratch;
    uint64_t seedBase = 1;
    int threads = 0;
    bool measureSpeed = true;
    /// Each render's wall-time limit here and now (time_limit.h); 0: the rubric's.
    double runSeconds = 0;
    /// A build without the solutions cannot check speed (measureSpeed false), but it still times
    /// the student's labs, for the speed ratios between them; the reference's ratios then come
    /// from the stored figures (lab_figures.json, by lab; 0 where none).
    bool timeWithoutSolutions = false;
    ByLab<double> storedSolutionSamplesPerSecond;
    /// The race check of a submitted lab (race_check.h), made once its correctness renders
    /// finished; its finding enters the correctness verdict (race_verdict.h). Empty: none.
    std::function<RaceFinding(Lab)> raceCheck;
};

/// `startUps`: the grading's start-up measurements, shared by the labs it grades.
LabGrade gradeLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps);

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

/// A lab that could not be graded at all (not submitted, does not compile): every check fails
/// with `reason` as its summary and diagnosis.
LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details);

} // namespace pathlab::grader
