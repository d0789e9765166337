#pragma once
/// The instructor-editable rubric (grader/rubric.json): points, thresholds, render sizes.

#include "checks/check_kind.h"
#include "checks/late_policy.h"
#include "checks/variant_settings.h"
#include "common/by_lab.h"

#include "pathlab/render/lab_registry.h"

#include <string>
#include <vector>

namespace pathlab::grader {

struct LabPoints {
    double correctness = 0, noise = 0, speed = 0;

    /// The points of one check.
    double of(CheckKind check) const {
        return check == CheckKind::Correctness ? correctness
               : check == CheckKind::Noise     ? noise
                                               : speed;
    }
};

/// What "as fast as the reference" means for a lab (rubric: speed.judged_by).
enum class SpeedMeasure {
    SamplesPerSecond, ///< samples/s: the lab as its handout specifies it, no cheaper, no dearer
    Efficiency,       ///< 1/(per-sample variance x time per sample): time to reach equal noise
};

/// The second parameters the analytic furnace is graded at, so that a lab that ignores
/// ctx.maxDepth (labs 1-3) or ctx.continueProb (lab 4) fails (rubric: parameter_check).
struct ParameterCheck {
    std::string scene = "furnace"; ///< a furnace of models/ (diagnosis.h's furnaceModel)
    int maxDepth = 5;
    float continueProb = 0.5f;
};

/// What the rubric sets for each lab apart.
struct LabRubric {
    LabPoints points;
    int correctnessSpp = 0; ///< samples per pixel of each correctness render (and timed run)
    SpeedMeasure speedJudgedBy = SpeedMeasure::SamplesPerSecond; ///< where the rubric is silent
};

/// Whether a regrade of the same files may lower a student's total (rubric:
/// regrades.lower_scores). Until the instructor says, a lowered total is withheld from the LMS
/// export, so that no student loses points that nobody decided to take.
enum class LowerScores {
    Undecided,  ///< not in the rubric: the gradebook says so, lms.csv keeps the LMS's grade
    Replace,    ///< "replace": the regrade's total counts, lower or not
    KeepHigher, ///< "keep_higher": the higher of the earlier gradings' totals counts
};

/// The rubric's spelling of a choice ("" for Undecided).
const char* lowerScoresName(LowerScores choice);

struct Rubric {
    ByLab<LabRubric> labs;
    int maxDepth = 3;
    float continueProb = 0.8f; ///< lab 4 is graded here: finite variance on VI2
    double alpha = 1e-3;       ///< family-wise false-fail rate of one correctness check
    int seeds = 10;
    int width = 64, height = 64, tiles = 4;
    std::vector<std::string> scenes; ///< public scenes, by name in models/
    double maxNoiseRatio = 1.5;
    std::string noiseScene;
    double minSpeedRatio = 0.75;
    int speedRuns = 5;        ///< interleaved pairs at a time (speed_check.h)
    double speedAlpha = 1e-3; ///< the chance that a lab at the threshold fails the speed check
    /// The correctness scene whose renders are timed (speed_check.h): one of `scenes`.
    std::string speedScene;
    ParameterCheck parameterCheck;
    double secondsPerRun = 30;
    long long memoryBytes = 4LL << 30;
    /// When Gradescope shows students the hidden scenes' verdicts
    /// (hidden_scenes.gradescope_visibility): visible, hidden, after_due_date or after_published.
    std::string hiddenScenesVisibility = "after_published";
    /// How many variants of the public scenes a batch grades on as hidden scenes when the
    /// instructor keeps none (hidden_scenes.variants; scene_variants.h); 0: none.
    int sceneVariants = 1;
    /// Per-student variants (the section "variants"; student_variant.h).
    VariantSettings variants;
    /// What a regrade that lowers a total does (regrades.lower_scores); not in `hash`: it
    /// decides which total the gradebook shows, not how any lab is graded or scored.
    LowerScores lowerScores = LowerScores::Undecided;
    /// What a late submission loses (the section "late"); not in `hash`, for the same reason.
    LatePolicy late;
    /// Gradescope's results.json carries a leaderboard (gradescope.leaderboard); not in `hash`:
    /// it shows figures, it grades nothing.
    bool gradescopeLeaderboard = false;
    /// A fingerprint of every setting (the file's JSON, reformatted, without "about"): each
    /// result records it, so that results graded under another rubric are never mixed.
    std::string hash;
    /// A fingerprint of the settings that decide what is measured: all but the points and the
    /// thresholds the measurements are judged by (noise.max_ratio, speed.min_ratio, speed.alpha,
    /// speed.judged_by) and Gradescope's visibility. Results measured under the same are judged
    /// again under a new rubric without rendering (a batch's re-score).
    std::string measurementHash;

    const LabRubric& forLab(Lab lab) const { return labs[lab]; }
};

/// Reads a rubric; throws InputError naming the file and the missing or wrong entry.
Rubric loadRubric(const std::string& path);

} // namespace pathlab::grader
