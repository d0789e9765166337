#include "checks/check_result.h"

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

double LabGrade::pointsAtRisk() const {
    double s = 0;
    for (const CheckResult& c : checks) s += !c.gradedHere && c.atRisk ? c.maxScore : 0;
    return s;
}

} // namespace pathlab::grader
