#pragma once
/// The correctness check: a lab's mean radiance, whole image and tile by tile, on every grading
/// scene against the reference (a t-test per region, Holm over all of them), with a retry on
/// fresh seeds; and the parameter check, the analytic furnace at a second maxDepth and
/// continueProb, so that a lab that ignores either fails.

#include "checks/check_result.h"
#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The verdict and what its renders leave for the other checks and the reports.
struct CorrectnessOutcome {
    CheckResult check;
    /// The trimmed per-sample variance of the renders on the rubric's noise scene (-1 if none
    /// finished), for the noise check.
    double noise = -1;
    std::vector<LabGrade::Pictures> pictures;
    bool rendersFinished = true; ///< false when a render crashed, hung or ran out
    /// The first attempt's images of the speed scene, one per seed (correctness_renders.h): the
    /// speed check's timed runs must render them again.
    std::vector<std::vector<float>> speedSceneImages;
};

CorrectnessOutcome checkCorrectness(const GraderSetup& setup, Lab lab);

/// The parameter check's scene: the rubric's parameter_check furnace rendered at its maxDepth
/// and continueProb, with the analytic values as its reference. Throws InputError when the scene
/// is not a furnace.
GradingScene parameterCheckScene(const Rubric& rubric);

/// A furnace of `model` at `path` rendered at the model's maxDepth and continueProb, its
/// reference the analytic values (no standard error), called `name` in feedback.
GradingScene analyticFurnaceScene(const Rubric& rubric, const std::string& path,
                                  const FurnaceModel& model, const std::string& name);

/// A render's failure on `scene` as feedback may show it: on a public scene (or one the instructor
/// reveals) the whole text, with what the lab printed; on a hidden one only what kind of failure
/// it was, in the grader's own words: nothing the lab printed, wrote or counted there, which it
/// could have made from the scene's files, and not the scene's name.
std::string failureAsShown(const std::string& failure, const std::string& kind,
                           const GradingScene& scene);

} // namespace pathlab::grader
