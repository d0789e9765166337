#pragma once
/// A batch's jobs: each submission graded by a child `grader submission` of its own, `jobs` at a
/// time, the gradebook written again after each, and each job's start and end in OUT/batch.log.

#include "commands/batch_selection.h"
#include "reports/gradebook.h"

#include "process/child_process.h"

#include <chrono>
#include <fstream>
#include <string>
#include <vector>

namespace pathlab::grader {

/// Now, as batch.log writes it: 2026-12-01T23:59:00 (local).
std::string timestamp();
/// The wall time since `start`, for the log and the last line.
double secondsSince(std::chrono::steady_clock::time_point start);
/// The ids, in order, as the gradebook and the similarity check name submissions.
std::vector<std::string> idsOf(const std::vector<Submission>& submissions);

/// A child grading one submission.
struct Job {
    ChildProcess child;
    Submission submission;
    std::chrono::steady_clock::time_point start;
};

/// Starts `grader submission` (argv) for `s`, writing what it prints to `log`.
Job startJob(const std::vector<std::string>& argv, const Submission& s, const std::string& log);

/// The gradebook's rows: each submission's stored result, pending while `queued` names it.
std::vector<GradebookEntry> gradebookEntries(const std::string& out,
                                             const std::vector<Submission>& submissions,
                                             const std::vector<std::string>& queued);

/// How a batch's jobs ended.
struct JobCounts {
    size_t done = 0, failed = 0; ///< failed: not graded (no result.json)
};

/// Grades `todo`, `jobs` at a time, each with the command line `childBase` followed by the
/// submission and its --out; after each job the gradebook is written again, those queued or
/// being graded in it as pending (similarity waits until all are graded).
JobCounts gradeInJobs(int jobs, const std::vector<std::string>& childBase,
                      const std::vector<Submission>& todo,
                      const std::vector<Submission>& submissions, const std::string& out,
                      const GradingNow& grading, std::ofstream& log);

} // namespace pathlab::grader
