#pragma once
/// The lobe check of a lab that writes a glossy lobe (lab 5): its sampleLobe and lobePdf, run on
/// inputs the grader draws, judged against the Phong lobe handout 05 derives
/// (pathlab/warp/phong_lobe_check.h). Part of correctness, as the race check is: a lab whose
/// routines are wrong fails correctness whatever its images show (a pair of another shape that
/// agree with each other renders the right mean, only noisier), with the routines' problems in
/// words naming the step (TODO lab5.1, lab5.2).

#include "checks/check_result.h"
#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The diagnosis of a lab failed by the lobe check, in the class summary's table.
inline constexpr const char* LobeDiagnosis = "lobe sampling or density wrong";

/// The chance that right routines fail the check (Šidák-shared among its exponents).
inline constexpr double LobeCheckFalseFailRate = 0.001;

/// Runs the check of `lab` (which must write a lobe) and adds its verdict to `correctness`:
/// fails it, the problems first in its details, or says in a detail that the routines agree with
/// the lobe.
void addLobeVerdict(const GraderSetup& setup, Lab lab, CheckResult& correctness);

} // namespace pathlab::grader
