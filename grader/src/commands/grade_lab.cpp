#include "commands/grade_lab.h"

#include "checks/correctness_check.h"
#include "checks/glossy_furnace_scene.h"
#include "checks/lobe_check.h"
#include "checks/noise_check.h"
#include "checks/pick_report.h"
#include "checks/race_verdict.h"
#include "checks/speed_check.h"
#include "checks/strategy_noise.h"

#include <chrono>

namespace pathlab::grader {

namespace {

/// `setup` with the scenes that grade `lab` alone (GradingScene::labs), the tilted glossy
/// furnace as this submission's variant of it (glossy_furnace_scene.h).
GraderSetup setupFor(const GraderSetup& setup, Lab lab) {
    GraderSetup own = setup;
    own.scenes.clear();
    for (const GradingScene& scene : setup.scenes) {
        if (!scene.grades(lab)) continue;
        if (scene.name == GlossyFurnaceScenes[1] && !scene.hidden)
            own.scenes.push_back(tiltedGlossyFurnaceVariant(
                setup.rubric, labVariantSeed(setup, lab), setup.scratch));
        else
            own.scenes.push_back(scene);
    }
    return own;
}

} // namespace

LabMeasurement measureLab(const GraderSetup& allLabs, Lab lab, StartUpTimes& startUps) {
    const GraderSetup setup = setupFor(allLabs, lab);
    LabMeasurement m;
    m.lab = lab;
    auto started = std::chrono::steady_clock::now();
    const auto lap = [&] {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - started).count();
        started = now;
        return seconds;
    };
    CorrectnessOutcome correctness = checkCorrectness(setup, lab);
    m.seconds.correctness = lap();
    // A lab that crashed or hung has failed already; the race check would only do it again.
    if (setup.raceCheck && correctness.rendersFinished) {
        addRaceVerdict(setup.raceCheck(lab), correctness.check);
        m.seconds.race = lap();
    }
    // A lab that writes a lobe has its routines judged too (lobe_check.h), also when its renders
    // failed: the routines may be why (a wrong sampler's weights overflow), and their own run
    // says so in its words.
    if (writesLobe(lab)) {
        addLobeVerdict(setup, lab, correctness.check);
        m.seconds.correctness += lap();
    }
    // Lab 6 failing where its lobe is right: the glossy furnaces' light is found by both
    // strategies, and a wrong sum of weights shows there first.
    if (combinesStrategies(lab) && !correctness.check.passed && correctness.rendersFinished)
        correctness.check.details.push_back(
            "lab 6: if the glossy furnaces are the scenes that differ and the lobe check passes, "
            "look at the weights: a direction's two, misWeight(p_light, p_lobe) in lab6.3 and "
            "misWeight(p_lobe, p_light) in lab6.4, must add up to one, each strategy's light "
            "weighted once (TODO lab6.2 to lab6.4); if lab 4's scenes differ too, at the path "
            "(TODO lab6.5)");
    // A lab that failed: where its picks and its divisions part, in words (pick_report.h). Lab 1
    // sends a ray for every component and picks none.
    if (!correctness.check.passed && correctness.rendersFinished && lab != Lab::Branching) {
        addPickTestReport(setup, lab, correctness.check);
        m.seconds.correctness += lap();
    }
    m.correctness = correctness.check;
    m.rendersFinished = correctness.rendersFinished;
    m.pictures = std::move(correctness.pictures);
    m.noise = measureNoise(setup, lab, correctness.noise);
    // Lab 6: its noise tile by tile against each strategy alone (strategy_noise.h), which, like
    // the noise figure, counts only for a correct lab.
    if (combinesStrategies(lab) && m.correctness.passed) {
        m.noise.strategies = measureStrategyTiles(setup, lab);
        m.seconds.correctness += lap();
    }
    m.speedMeasured = setup.measureSpeed;
    if (!setup.measureSpeed) return m;
    if (!m.rendersFinished) {
        // A lab that crashed or hung in 64x64 renders would do the same timed.
        m.speed.notTimed = "not measured: the lab's correctness renders failed, and speed counts "
                           "only for a correct lab";
        return m;
    }
    const bool correct = m.correctness.passed;
    const SampleVariances variances = correct && m.noise.student > 0
                                          ? SampleVariances{m.noise.student, m.noise.solution}
                                          : SampleVariances{};
    lap();
    m.speed = timeLab(setup, lab, {variances, correctness.speedSceneImages}, startUps);
    m.seconds.speed = lap();
    return m;
}

LabGrade gradeLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps,
                  LabMeasurement* measured) {
    const LabMeasurement m = measureLab(setup, lab, startUps);
    LabGrade grade = judgeLab(setup.rubric, m);
    if (measured) *measured = m;
    if (!setup.timeWithoutSolutions) return grade;
    CheckResult speed;
    speed.kind = CheckKind::Speed;
    speed.maxScore = setup.rubric.forLab(lab).points.speed;
    if (!m.rendersFinished) {
        speed.summary = "not measured: the lab's correctness renders failed, and speed counts "
                        "only for a correct lab";
        grade.checks.push_back(speed);
        return grade;
    }
    const SpeedOutcome timed =
        timeWithoutSolutions(setup, lab, grade.checks.front().passed, startUps);
    grade.checks.push_back(timed.check);
    grade.studentSamplesPerSecond = timed.studentSamplesPerSecond;
    grade.solutionSamplesPerSecond = timed.solutionSamplesPerSecond;
    grade.studentRays = timed.studentRays;
    return grade;
}

} // namespace pathlab::grader
