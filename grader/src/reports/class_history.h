#pragma once
/// The class over the term: each finished batch adds the class's figures then (the mean total,
/// each lab's mean and correctness pass rate) to OUT/history.jsonl, and the summary page draws
/// them, run after run, as a table and a chart: what weekly batches over a term's repositories
/// show of a class catching up, or of a lab that stays hard.

#include "reports/gradebook.h"

#include <map>
#include <string>
#include <vector>

namespace pathlab::grader {

/// The class's figures when a batch finished.
struct ClassFigures {
    std::string at;                        ///< UTC, ISO 8601
    int graded = 0;                        ///< submissions with a total under the grading then
    int submissions = 0;                   ///< in the gradebook
    double meanTotal = 0;                  ///< mean total, % of the maximum
    std::map<std::string, double> labMean; ///< lab -> mean score, % of its maximum
    std::map<std::string, double> labCorrectness; ///< lab -> % of those graded passing correctness
};

/// The figures of `entries` under the grading now, at `at`.
ClassFigures classFiguresNow(const std::vector<GradebookEntry>& entries, const GradingNow& now,
                             const std::string& at);

/// OUT/history.jsonl, oldest first; a line it cannot read is left out.
std::vector<ClassFigures> readClassHistory(const std::string& out);

/// Writes `history` as OUT/history.jsonl (atomically): what was read, a batch's figures added.
void writeClassHistory(const std::string& out, const std::vector<ClassFigures>& history);

/// The summary page's "Over time" section: a table of the batches and, from two on, a chart of
/// the mean total and each lab's mean, every label inside its SVG.
std::string classHistoryHtml(const std::vector<ClassFigures>& history);

} // namespace pathlab::grader
