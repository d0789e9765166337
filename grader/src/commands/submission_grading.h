#pragma once
/// Grading one submitted set of labs: take its files in, compile them in the sandbox, run the
/// checks in the sandbox, and write its feedback and its result.

#include "checks/grader_setup.h"
#include "checks/lab_measurement.h"
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

/// Where a submission's grading time went, in wall-clock seconds (batch.log, summary.html).
struct SubmissionSeconds {
    double intake = 0, compile = 0; ///< taking the files in; compiling and linking its labs
    PhaseSeconds labs;              ///< summed over its labs
};

struct SubmissionOutcome {
    std::string id;
    std::string rubricHash, scenesHash; ///< what it was graded under
    /// The rubric's settings that decide what is measured (Rubric::measurementHash), and
    /// whether speed was: a result whose are those of now is re-scored, not graded again.
    std::string measurementHash;
    bool speedMeasured = true;
    std::string filesHash; ///< of the lab files taken, by name
    std::string status;    ///< "graded", or why it could not be ("no lab files found", ...)
    GradeReport report;
    std::vector<LabMeasurement> measurements; ///< one per lab, as report.labs
    Intake intake;
    SubmissionSeconds seconds;
    int attempt = 1; ///< this grading's number among the submission's (1: its first)
    /// How: "graded", or "re-scored" from an earlier attempt's measurements.
    std::string how = "graded";
};

/// Grades `submission` with its working files in `folder` (its renders' in `scratch`, a folder
/// of this grading's own), and writes there, in this order, feedback.json (the grader's JSON
/// report), index.html, and result.json (a summary for the gradebook). result.json is written
/// last and atomically: its presence means done. `id`: the student's id, where not the
/// submission's name (grader submission --id).
SubmissionOutcome gradeSubmission(const SubmissionGrader& grader, const std::string& submission,
                                  const std::string& folder, const std::string& scratch,
                                  const std::string& id = "");

/// result.json's text for an outcome.
std::string resultJson(const SubmissionOutcome& outcome, const std::string& submission);

/// The hash of the lab files taken from a submission (Intake::taken, copied into `folder`):
/// what tells a changed submission from one already graded.
std::string labFilesHash(const Intake& intake, const std::string& folder);

/// Keeps a submission's grading as an attempt before another replaces it: FOLDER's result.json,
/// feedback.json, measurements.json, index.html, grader.log and pictures/ move to
/// FOLDER/attempts/N/. Returns the number the next grading takes (1 where there was none).
int archiveAttempt(const std::string& folder);

/// Writes FOLDER's feedback.json, index.html, measurements.json and, last and atomically,
/// result.json for `outcome`, the earlier attempts (attempts/) listed on the page.
void writeGrading(const SubmissionOutcome& outcome, const std::string& submission,
                  const std::string& folder);

} // namespace pathlab::grader
