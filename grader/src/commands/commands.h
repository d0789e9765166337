#pragma once
/// The grader's commands; each returns the exit status.

#include "checks/rubric.h"
#include "commands/arguments.h"
#include "reports/reports.h"

#include <string>

namespace pathlab::grader {

/// Writes the reports the options ask for (--json, --junit, --gradescope, --html).
void writeReports(const Arguments& a, const Rubric& rubric, const GradeReport& report);

/// Grades the labs of this build (or of --viewer): exit 0 when every check passed, 1 if not.
int gradeBuild(const Arguments& a, const Rubric& rubric, const std::string& scratch);
/// Measures grader/references/ (or --references) from the solutions.
int makeReferences(const Arguments& a, const Rubric& rubric, const std::string& scratch);
/// Grades one submission in the sandbox into --out: exit 0 when graded (whatever the score).
int gradeOneSubmission(const Arguments& a, const Rubric& rubric, const std::string& scratch);
/// Grades a folder of submissions into --out; a submission that fails never stops it.
int runBatch(const Arguments& a, const Rubric& rubric, const std::string& scratch);
/// Merges the outputs of batch shards into one gradebook in --out.
int mergeBatches(const Arguments& a);
/// Writes the rubric's scene variants into the folder named (grader make-variants).
int makeVariants(const Arguments& a, const Rubric& rubric);
/// Keeps a graded class's lab files as tokens for later terms (grader keep-term).
int keepTerm(const Arguments& a);
/// Writes each student's variant folder, --out/ID/ (student_variant.h).
int makeStudentVariants(const Arguments& a, const Rubric& rubric, const std::string& scratch);
/// The seed of scene variants: --variant-seed, else the one kept in the file `keptIn`, else a
/// new random one.
uint64_t variantSeed(const Arguments& a, const std::string& keptIn);

} // namespace pathlab::grader
