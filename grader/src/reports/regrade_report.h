#pragma once
/// What a regrade changed: a submission's grading compared with the one before it (kept in
/// OUT/submissions/ID/attempts/N), lab by lab and check by check, with why it was graded again
/// (the rubric, the scenes, the kit, the student's files, or an instructor asking); and what a
/// regrade of the same files lowered, which the rubric's regrades.lower_scores decides about.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// One check whose points a grading changed; a check one of the two gradings did not make
/// (speed under --no-speed) has no score there.
struct ScoreChange {
    std::string lab, check;
    std::optional<double> before, after;
};

/// A grading against the attempt before it.
struct RegradeComparison {
    std::string id;
    int fromAttempt = 0, toAttempt = 0;
    double before = 0, after = 0, maxBefore = 0, maxAfter = 0;
    std::vector<std::string> reasons; ///< why it was graded again, in words
    std::vector<ScoreChange> changes; ///< the checks whose points changed
    bool resubmitted = false;         ///< the student's files changed: a new submission
};

/// The grading `result` (OUT/submissions/ID/result.json, in `folder`) against the attempt before
/// it; none for a first grading, or where the attempt before is missing or unreadable.
std::optional<RegradeComparison> compareWithAttemptBefore(const std::string& id,
                                                          const std::string& folder,
                                                          const nlohmann::json& result);

/// An earlier grading's total, higher than the one now.
struct EarlierTotal {
    int attempt = 0;
    double score = 0;
};

/// The highest total of the earlier gradings of the same files (the same hash and commit) out
/// of the same maximum, where it is higher than `result`'s: what regrades lowered. A grading of
/// other files (a resubmission) is the student's own new grade, never compared.
std::optional<EarlierTotal> higherEarlierTotal(const std::string& folder,
                                               const nlohmann::json& result);

/// "alice: attempt 1 -> 2 (the rubric's points or thresholds changed): 40 / 48 -> 46 / 58;
/// uniform noise 0 -> 6", one line, for the terminal and batch.log.
std::string regradeLine(const RegradeComparison& c);

/// regrades.csv: a row per changed check of each comparison (a row with check "total" first),
/// and a row for a comparison that changed nothing.
std::string regradesCsv(const std::vector<RegradeComparison>& comparisons);

/// The summary page's table of the same.
std::string regradesHtml(const std::vector<RegradeComparison>& comparisons);

} // namespace pathlab::grader
