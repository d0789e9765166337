#pragma once
/// The three checks of one lab, in order: correctness, noise, frame rate.

#include "checks/check_result.h"
#include "checks/grader_setup.h"
#include "checks/rubric.h"
#include "isolation/start_up_times.h"

#include "pathlab/lab_registry.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// `startUps`: the grading's start-up measurements, shared by the labs it grades.
LabGrade gradeLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps);

/// A lab that could not be graded at all (not submitted, does not compile): every check fails
/// with `reason` as its summary and diagnosis.
LabGrade ungradedLab(const Rubric& rubric, Lab lab, bool measureSpeed, const std::string& reason,
                     const std::vector<std::string>& details);

} // namespace pathlab::grader
