#include "checks/noise_check.h"

#include "checks/number_text.h"
#include "diagnosis/diagnosis_table.h"

#include <algorithm>

namespace pathlab::grader {

NoiseMeasurement measureNoise(const GraderSetup& setup, Lab lab, double noise) {
    const Rubric& r = setup.rubric;
    const auto scene =
        std::find_if(setup.scenes.begin(), setup.scenes.end(),
                     [&](const GradingScene& s) { return s.reference.scene == r.noiseScene; });
    const GradingScene& noiseScene = scene != setup.scenes.end() ? *scene : setup.scenes.front();
    return {noise, noiseScene.reference.noise[lab], noiseScene.reference.scene};
}

/// The noise of the correctness runs on the noise scene against the reference solution's. Like
/// speed, it counts only for a correct lab: a lab that renders too little light is also quiet.
NoiseOutcome judgeNoise(const Rubric& r, Lab lab, bool correct, const NoiseMeasurement& m) {
    NoiseOutcome outcome;
    CheckResult& check = outcome.check;
    check.kind = CheckKind::Noise;
    check.maxScore = r.forLab(lab).points.noise;
    if (m.student < 0) {
        check.summary = "could not be measured: the lab's renders failed (see correctness)";
        return outcome;
    }
    if (!correct) {
        // A wrong image's variance says nothing about the estimator: a lab missing light is
        // also quiet, one with NaN or an extra factor noisy. No ratio, then, to mislead.
        check.summary = "not compared: noise counts only for a correct lab";
        return outcome;
    }
    const double ratio = m.student / m.solution;
    outcome.variances = {m.student, m.solution};
    check.summary = "per-sample variance " + significant(ratio, 3) +
                    " times the reference solution's (at most " + significant(r.maxNoiseRatio, 2) +
                    ") on " + m.scene;
    check.passed = ratio <= r.maxNoiseRatio;
    check.score = check.passed ? check.maxScore : 0;
    if (!check.passed) {
        check.diagnosis = "too noisy";
        check.details.push_back("variance per sample: yours " + significant(m.student, 4) +
                                ", the reference's " + significant(m.solution, 4));
        check.details.push_back(hintFor(HintTopic::TooNoisy, lab));
    }
    return outcome;
}

} // namespace pathlab::grader
