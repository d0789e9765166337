#pragma once
/// Grading one submitted set of labs: take its files in, compile them in the sandbox, run the
/// checks in the sandbox, and write its feedback and its result.

#include "checks/grader_setup.h"
#include "checks/race_check.h"
#include "isolation/lab_library.h"
#include "isolation/submission_intake.h"
#include "reports/reports.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// What the gradings of one batch share.
struct SubmissionGrader {
    LabBuild build;
    LabKit kit;
    Rubric rubric;
    std::vector<GradingScene> scenes;
    TimingPolicy timing;
    std::vector<int> workCpus; ///< cores for compiling and the correctness renders (empty: any)
    uint64_t seedBase = 1;
    int threads = 0; ///< threads per correctness render (0: all cores)
    bool measureSpeed = true;
    std::string scenesHash; ///< grading_scenes.h: recorded in result.json with the rubric's hash
    /// The race check (race_check.h); when unavailable, no lab is checked, none failed for it.
    RaceCheckRuntime raceCheck;
};

struct SubmissionOutcome {
    std::string id;
    std::string rubricHash, scenesHash; ///< what it was graded under
    std::string filesHash;              ///< of the lab files taken, by name
    std::string status; ///< "graded", or why it could not be ("no lab files found", ...)
    GradeReport report;
    Intake intake;
};

/// Grades `submission` with its working files in `folder` (its renders' in `scratch`, a folder
/// of this grading's own), and writes there, in this order, feedback.json (the grader's JSON
/// report), index.html, and result.json (a summary for the gradebook). result.json is written
/// last and atomically: its presence means done.
SubmissionOutcome gradeSubmission(const SubmissionGrader& grader, const std::string& submission,
                                  const std::string& folder, const std::string& scratch);

/// result.json's text for an outcome.
std::string resultJson(const SubmissionOutcome& outcome, const std::string& submission);

} // namespace pathlab::grader
