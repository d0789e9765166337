#include "checks/noise_check.h"

#include "checks/number_text.h"
#include "checks/strategy_noise.h"
#include "diagnosis/diagnosis_table.h"

#include <algorithm>

namespace pathlab::grader {

namespace {

/// Lab 6: its worst tile of veach_plates against the better strategy alone, into `check`.
void judgeStrategyTiles(const StrategyTiles& tiles, CheckResult& check) {
    if (!tiles.failure.empty()) {
        check.passed = false;
        check.diagnosis = "strategies not compared";
        check.details.push_back(tiles.failure);
        return;
    }
    // The noise of an image of something else says nothing (a lab that renders veach_plates
    // quietly wrong): it fails, with the tile that shows it.
    if (const std::string wrong = strategyMeanDisagreement(tiles); !wrong.empty()) {
        check.passed = false;
        check.diagnosis = "strategies not compared";
        check.details.push_back(wrong + ": the noise of an image that does not average to the "
                                        "scene's is not compared with the strategies'");
        return;
    }
    // Images that barely vary between seeds are not a sampler's, whatever their tiles' ratios.
    if (const double share = strategyVarianceShare(tiles); share < MinStrategyVarianceShare) {
        check.passed = false;
        check.diagnosis = "strategies not compared";
        check.details.push_back(
            "your renders of " + std::string(StrategyScene) + " vary between seeds " +
            significant(share, 2) +
            " times as much as the better strategy's alone, over the "
            "plates: no estimator of " +
            std::to_string(StrategySpp) +
            " samples per pixel is that quiet, so their noise is not compared (does the lab "
            "keep values from one sample or seed for the next?)");
        return;
    }
    const WorstStrategyTile worst = worstStrategyTile(tiles);
    if (worst.index < 0) {
        check.passed = false;
        check.diagnosis = "strategies not compared";
        check.details.push_back("lab 6's tiles of " + std::string(StrategyScene) +
                                " were not measured");
        return;
    }
    check.summary += "; on " + std::string(StrategyScene) + ", the worst tile " +
                     significant(worst.ratio, 3) + " times the better strategy's alone (at most " +
                     significant(MaxStrategyTileRatio, 2) + ")";
    if (tiles.strategiesByLab)
        check.details.push_back(
            "the strategies alone were your lab's own, rendered through ctx.strategyWeight as "
            "make strategies renders them: this build has no reference solution; your "
            "instructor's grader renders the reference solution's");
    if (worst.ratio <= MaxStrategyTileRatio) return;
    check.passed = false;
    if (check.diagnosis.empty()) check.diagnosis = "noisier than the better strategy";
    check.details.push_back(describeStrategyTile(tiles, worst));
    check.details.push_back(
        "multiple importance sampling is never much noisier than the better of its strategies "
        "where the weights follow a heuristic on both densities, in the same measure: check "
        "misWeight (TODO lab6.2, the power heuristic, not a constant) and that lab6.3 and "
        "lab6.4 pass it ctx.sampleLight's pdf and ctx.lightPdf, per unit solid angle, beside "
        "lobePdf (`make strategies` shows the three images side by side)");
}

} // namespace

NoiseMeasurement measureNoise(const GraderSetup& setup, Lab lab, double noise) {
    const Rubric& r = setup.rubric;
    const auto scene =
        std::find_if(setup.scenes.begin(), setup.scenes.end(),
                     [&](const GradingScene& s) { return s.reference.scene == r.noiseScene; });
    const GradingScene& noiseScene = scene != setup.scenes.end() ? *scene : setup.scenes.front();
    return {noise, noiseScene.reference.noise[lab], noiseScene.reference.scene, {}};
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
    if (!check.passed) {
        check.diagnosis = "too noisy";
        check.details.push_back("variance per sample: yours " + significant(m.student, 4) +
                                ", the reference's " + significant(m.solution, 4));
        check.details.push_back(hintFor(HintTopic::TooNoisy, lab));
    }
    if (combinesStrategies(lab)) judgeStrategyTiles(m.strategies, check);
    check.score = check.passed ? check.maxScore : 0;
    return outcome;
}

} // namespace pathlab::grader
