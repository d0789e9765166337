#pragma once
/// A class's results: gradebook.csv (a row per submission, a column per lab and check),
/// lms.csv (the totals, for an LMS to import), regrades.csv (what each submission's last regrade
/// changed) and summary.html (the score histogram, the most common diagnoses, the similar pairs,
/// the regrades), made from the submissions' result.json files and their earlier attempts.

#include "checks/rubric.h"
#include "reports/regrade_report.h"
#include "reports/submission_time.h"

#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// One submission's line: its result.json, or for a submission not graded, its id, path and why.
struct GradebookEntry {
    std::string id, submission;
    nlohmann::json result; ///< null when not graded
    std::string problem;   ///< why not graded
    bool pending = false;  ///< waiting in a batch that is running: not graded yet
    /// An earlier grading of the same files with a higher total: what a regrade lowered.
    std::optional<EarlierTotal> higherEarlier;
};

/// What the gradebook is written against: the grading as it is now. A result graded under
/// another rubric, other scenes or another maximum is stale: shown as such, its total left out
/// where its maximum differs, so that the gradebook never mixes maxima.
struct GradingNow {
    std::string rubricHash, scenesHash;
    std::string measurementHash; ///< Rubric::measurementHash
    bool measuresSpeed = true;   ///< not --no-speed
    double maxScore = 0;
    std::optional<long long> deadline;                ///< --deadline, seconds since 1970
    SubmissionTimes times;                            ///< --times, over what results say
    LowerScores lowerScores = LowerScores::Undecided; ///< the rubric's regrades.lower_scores
    LatePolicy late;                                  ///< the rubric's late policy
};

/// Two submissions' files of one lab that are alike (similarity.h), for the summary.
struct SimilarLabs {
    std::string first, second, lab;
    double similarity = 0;
};

/// Reads OUT/submissions/ID/result.json, and its earlier attempts for a higher total; an entry
/// with a problem where there is none.
GradebookEntry readGradebookEntry(const std::string& out, const std::string& id,
                                  const std::string& submission);

/// Why a result does not fit the grading now ("" if it does): another rubric, other scenes,
/// another maximum.
std::string staleness(const nlohmann::json& result, const GradingNow& now);

/// What a result that does not fit the grading now needs: judged again from its measurements
/// (only the rubric's points or thresholds changed), or graded again (its scenes, the kit, what
/// the rubric measures, or whether speed is, changed; or it kept no measurements).
enum class Regrade { None, Rescore, Measure };
Regrade regradeNeeded(const nlohmann::json& result, const GradingNow& now);

/// The total that counts for `e` under the grading now: none where its maximum is not today's;
/// under regrades.lower_scores keep_higher, an earlier grading's higher total of the same files.
std::optional<double> countedTotal(const GradebookEntry& e, const GradingNow& now);

/// Writes OUT/gradebook.csv, OUT/lms.csv, OUT/regrades.csv and OUT/summary.html (atomically),
/// rows in the order of `entries`; the summary lists the `similar` pairs, or says they come once
/// the batch is done. A batch done (`similar` given) adds the class's figures to
/// OUT/history.jsonl, which the summary draws over time (class_history.h).
void writeGradebook(const std::string& out, const std::vector<GradebookEntry>& entries,
                    const GradingNow& now, const std::optional<std::vector<SimilarLabs>>& similar);

} // namespace pathlab::grader
