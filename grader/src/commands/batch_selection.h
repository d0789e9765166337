#pragma once
/// Which submissions `grader batch` grades: those named on the command line (this shard's), and
/// of those the ones not graded yet or graded under another grading (--force, --only,
/// --keep-stale), with what is kept as it is said in words.

#include "commands/arguments.h"
#include "reports/gradebook.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace pathlab::grader {

/// A submission of a batch: where it is, and the id its feedback and gradebook row go by.
struct Submission {
    std::string path, id;
};

/// The submissions named on the command line: each folder's entries (a folder of
/// submissions), or a .zip/.tar.gz given directly; sorted by id, this shard's only.
std::vector<Submission> listSubmissions(const Arguments& a);

/// Whether a submission goes by `id`: --only and --times name submissions by it.
bool hasId(const std::vector<Submission>& submissions, const std::string& id);

/// Throws InputError for an id of --only that names no submission (a typing error), before the
/// batch writes anything.
void requireKnownIds(const std::vector<std::string>& only,
                     const std::vector<Submission>& submissions);

/// What a submission holds now, to tell it from what was graded: the hash of its lab files as
/// the intake takes them, and a repository's commit.
struct SubmittedFiles {
    std::string filesHash, commit;
};

/// The submissions a batch grades, those it judges again from their measurements, and how many
/// of the others it keeps as they are, by reason.
struct Selection {
    std::vector<Submission> todo;
    std::vector<Submission> rescore;  ///< only the rubric's points or thresholds changed
    std::vector<std::string> changed; ///< ids graded again for their files changed
    size_t current = 0, staleKept = 0, staleRegraded = 0, notNamed = 0;
};

/// What to grade, from the results stored in `out`: everything not graded yet, what changed
/// since it was graded (`now`: each graded submission's files as they are), and what was graded
/// under another rubric, other scenes or another maximum (unless --keep-stale): judged again
/// from its measurements where only the rubric's points or thresholds changed, graded again
/// otherwise; --force: everything; --only: those named.
Selection selectSubmissions(const Arguments& a, const std::vector<Submission>& submissions,
                            const std::string& out, const GradingNow& grading,
                            const std::map<std::string, SubmittedFiles>& now);

/// Says on standard error why the submissions not graded now are kept, and which stale ones are
/// graded again.
void sayWhatIsKept(const Selection& selection);

} // namespace pathlab::grader
