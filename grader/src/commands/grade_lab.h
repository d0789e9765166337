#pragma once
/// The three checks of one lab, in order: correctness, noise, frame rate. What they measure
/// (lab_measurement.h) is kept; the verdict is judged from it.

#include "checks/check_result.h"
#include "checks/grader_setup.h"
#include "checks/lab_measurement.h"
#include "checks/rubric.h"
#include "isolation/start_up_times.h"

#include "pathlab/render/lab_registry.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// Runs the checks' renders of `lab`. `startUps`: the grading's start-up measurements, shared by
/// the labs it grades.
LabMeasurement measureLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps);

/// measureLab, judged under the setup's rubric; in a build without the reference solutions, the
/// student's own timed runs for the speed check (graded by the instructor).
LabGrade gradeLab(const GraderSetup& setup, Lab lab, StartUpTimes& startUps,
                  LabMeasurement* measured = nullptr);

} // namespace pathlab::grader
