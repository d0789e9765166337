#include "commands/grade_lab.h"

#include "checks/correctness_check.h"
#include "checks/noise_check.h"
#include "checks/race_verdict.h"
#include "checks/speed_check.h"

namespace pathlab::grader {

LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details) {
    LabGrade grade;
    grade.lab = lab;
    for (CheckKind kind : AllChecks) {
        if (kind == CheckKind::Speed && !measureSpeed) continue;
        CheckResult check;
        check.kind = kind;
        check.maxScore = rubric.forLab(lab).points.of(kind);
        check.summary = reason;
        check.diagnosis = reason;
        if (kind == CheckKind::Correctness) check.details = details;
        grade.checks.push_back(check);
    }
    return grade;
}

LabGrade gradeLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps) {
    LabGrade grade;
    grade.lab = lab;
    CorrectnessOutcome correctness = checkCorrectness(setup, lab);
    // A lab that crashed or hung has failed already; the race check would only do it again.
    if (setup.raceCheck && correctness.rendersFinished)
        addRaceVerdict(setup.raceCheck(lab), correctness.check);
    const bool correct = correctness.check.passed;
    grade.checks.push_back(correctness.check);
    grade.pictures = std::move(correctness.pictures);
    grade.rendersFinished = correctness.rendersFinished;
    const NoiseOutcome noise = checkNoise(setup, lab, correct, correctness.noise);
    grade.checks.push_back(noise.check);
    grade.studentVariance = noise.variances.student;
    grade.solutionVariance = noise.variances.solution;
    if (!setup.measureSpeed && !setup.timeWithoutSolutions) return grade;
    if (!grade.rendersFinished) {
        // A lab that crashed or hung in 64x64 renders would do the same in longer ones.
        CheckResult speed;
        speed.kind = CheckKind::Speed;
        speed.maxScore = setup.rubric.forLab(lab).points.speed;
        speed.summary = "not measured: the lab's correctness renders failed, and speed counts "
                        "only for a correct lab";
        grade.checks.push_back(speed);
        return grade;
    }
    const SpeedOutcome speed =
        checkSpeed(setup, lab, {correct, noise.variances, correctness.speedSceneImages}, startUps);
    grade.checks.push_back(speed.check);
    grade.studentSamplesPerSecond = speed.studentSamplesPerSecond;
    grade.solutionSamplesPerSecond = speed.solutionSamplesPerSecond;
    grade.studentRays = speed.studentRays;
    grade.solutionRays = speed.solutionRays;
    grade.efficiencyRatio = speed.efficiencyRatio;
    return grade;
}

} // namespace pathlab::grader
