#pragma once
/// How the race check's finding enters the correctness verdict. A data race between render
/// threads in the lab's own code fails correctness (diagnosis RaceDiagnosis), whatever the image
/// shows: the image of a program with a data race is undefined behaviour, which on another
/// machine, thread count or compiler may differ, and which the statistical check passed only by
/// chance. Races are not scored apart: the check names stay correctness, noise, speed.

#include "checks/check_result.h"
#include "checks/race_report.h"

namespace pathlab::grader {

/// The diagnosis of a lab failed for a data race, in the class summary's table.
inline constexpr const char* RaceDiagnosis = "data race between render threads";

/// Adds `finding` to `correctness`: fails it for a race (its lines first in the details), says
/// in a detail that the check found none, or why it could not be made (never failing for that).
void addRaceVerdict(const RaceFinding& finding, CheckResult& correctness);

} // namespace pathlab::grader
