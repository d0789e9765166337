#include "grading.h"

#include "correctness_check.h"
#include "noise_check.h"
#include "speed_check.h"

namespace pathlab::grader {

double LabGrade::score() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? c.score : 0;
    return s;
}

double LabGrade::maxScore() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? c.maxScore : 0;
    return s;
}

double LabGrade::pointsNotGradedHere() const {
    double s = 0;
    for (const CheckResult& c : checks) s += c.gradedHere ? 0 : c.maxScore;
    return s;
}

LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details) {
    LabGrade grade;
    grade.lab = lab;
    const LabPoints& points = rubric.points[static_cast<int>(lab)];
    std::vector<std::pair<std::string, double>> checks = {{"correctness", points.correctness},
                                                          {"noise", points.noise}};
    if (measureSpeed) checks.push_back({"speed", points.speed});
    for (const auto& [name, maxScore] : checks) {
        CheckResult check;
        check.name = name;
        check.maxScore = maxScore;
        check.summary = reason;
        check.diagnosis = reason;
        if (name == "correctness") check.details = details;
        grade.checks.push_back(check);
    }
    return grade;
}

LabGrade gradeLab(const GraderSetup& setup, Lab lab) {
    LabGrade grade;
    grade.lab = lab;
    double noise = -1; // the noise figure of the correctness renders on the noise scene
    grade.checks.push_back(checkCorrectness(setup, lab, grade, noise));
    grade.checks.push_back(checkNoise(setup, lab, grade.checks[0].passed, noise, grade));
    if (!setup.measureSpeed && !setup.timeWithoutSolutions) return grade;
    if (grade.rendersFinished) {
        grade.checks.push_back(checkSpeed(setup, lab, grade.checks[0].passed, grade));
    } else {
        // A lab that crashed or hung in 64x64 renders would do the same in longer ones.
        CheckResult speed;
        speed.name = "speed";
        speed.maxScore = setup.rubric.points[static_cast<int>(lab)].speed;
        speed.summary = "not measured: the lab's correctness renders failed, and speed counts "
                        "only for a correct lab";
        grade.checks.push_back(speed);
    }
    return grade;
}

} // namespace pathlab::grader
