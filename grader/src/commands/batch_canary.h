#pragma once
/// The canary: before anyone is graded, the reference solutions, graded as a submission on
/// every scene (speed left out: against themselves it measures only the machine), must get full
/// marks, or the references, the scenes or the rubric are wrong and every grade would be too.

#include "checks/rubric.h"
#include "reports/gradebook.h"

#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// The most a submission can score under this rubric, as this batch grades (speed or not).
double maxScoreNow(const Rubric& rubric, bool speed);

/// Grades the canary into OUT/.canary and throws InputError, saying what failed, when the
/// solutions do not get full marks. Skipped while the grading it passed is unchanged
/// (OUT/.canary/passed holds its fingerprint); judged again from its measurements where only
/// the rubric's points or thresholds changed since (a threshold can fail the solutions too);
/// otherwise graded, once `prepare` has made ready what a grading needs (`childBase`, the
/// gradings' command line, is filled in by it).
void runCanary(const std::vector<std::string>& childBase, const std::string& solutions,
               const std::string& out, const GradingNow& now, const Rubric& rubric,
               const std::string& references, const std::function<void()>& prepare,
               std::ofstream& log);

} // namespace pathlab::grader
