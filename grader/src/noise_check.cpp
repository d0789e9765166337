#include "noise_check.h"

#include "check_support.h"

#include <algorithm>

namespace pathlab::grader {

/// The noise of the correctness runs on the noise scene against the reference solution's. Like
/// speed, it counts only for a correct lab: a lab that renders too little light is also quiet.
CheckResult checkNoise(const GraderSetup& setup, Lab lab, bool correct, double noise,
                       LabGrade& grade) {
    const Rubric& r = setup.rubric;
    CheckResult check;
    check.name = "noise";
    check.maxScore = r.points[static_cast<int>(lab)].noise;
    if (noise < 0) {
        check.summary = "could not be measured: the lab's renders failed (see correctness)";
        return check;
    }
    if (!correct) {
        // A wrong image's variance says nothing about the estimator: a lab missing light is
        // also quiet, one with NaN or an extra factor noisy. No ratio, then, to mislead.
        check.summary = "not compared: noise counts only for a correct lab";
        return check;
    }
    const auto scene = std::find_if(setup.scenes.begin(), setup.scenes.end(), [&](const GradingScene& s) {
        return s.reference.scene == r.noiseScene;
    });
    const GradingScene& noiseScene = scene != setup.scenes.end() ? *scene : setup.scenes.front();
    const double student = noise;
    const double solution = noiseScene.reference.noise[static_cast<int>(lab)];
    const double ratio = student / solution;
    grade.studentVariance = student;
    grade.solutionVariance = solution;
    check.summary = format("per-sample variance %.3g times the reference solution's (at most %.2g) on ", ratio, r.maxNoiseRatio) +
                    noiseScene.reference.scene;
    check.passed = ratio <= r.maxNoiseRatio;
    check.score = check.passed ? check.maxScore : 0;
    if (!check.passed) {
        check.diagnosis = "too noisy";
        check.details.push_back(format("variance per sample: yours %.4g, the reference's %.4g", student, solution));
        if (lab == Lab::Importance)
            check.details.push_back("an importance pick that picks uniformly, or that picks components "
                                    "whose reflectance is zero, is this noisy; the probabilities "
                                    "should follow reduceMax(Kd), reduceMax(Ks), reduceMax(Kt)");
        else if (lab == Lab::Roulette)
            check.details.push_back("Russian roulette should pick the component by importance, as in lab 3");
        else
            check.details.push_back("more noise than the reference at the same mean: is a component "
                                    "sampled with the wrong probability, or a random number reused?");
    }
    return check;
}

} // namespace pathlab::grader
