// grader merge: the gradebooks of batch shards (grader batch --shard, run on several machines)
// as one.
#include "commands/commands.h"
#include "commands/output_lock.h"
#include "reports/gradebook.h"
#include "reports/submission_time.h"
#include "similarity/class_similarity.h"
#include "similarity/side_by_side.h"

#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

/// The grading a shard's gradebook was written against (its batch.json).
GradingNow shardGrading(const std::string& shard, std::string& deadline, std::string& times) {
    std::ifstream in(shard + "/batch.json");
    if (!in) throw InputError(shard + ": not a batch's output (no batch.json in it)");
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        GradingNow now;
        now.rubricHash = j.at("rubric_hash");
        now.scenesHash = j.at("scenes_hash");
        now.maxScore = j.at("max_score");
        now.late = latePolicyFromJson(j.value("late", nlohmann::json()));
        const std::string lower = j.value("lower_scores", "");
        now.lowerScores = lower == "replace"       ? LowerScores::Replace
                          : lower == "keep_higher" ? LowerScores::KeepHigher
                                                   : LowerScores::Undecided;
        deadline = j.value("deadline", "");
        times = j.value("times", "");
        return now;
    } catch (const nlohmann::json::exception& e) {
        throw InputError(shard + "/batch.json: " + e.what());
    }
}

} // namespace

int mergeBatches(const Arguments& a) {
    std::vector<GradebookEntry> all;
    GradingNow now;
    std::string deadline = a.deadline, times = a.times;
    // Every shard checked before anything is copied: a refused merge writes nothing.
    for (const std::string& shard : a.inputs) {
        if (!fs::is_directory(fs::path(shard) / "submissions"))
            throw InputError(shard + ": not a batch's output (no submissions/ in it)");
        std::string shardDeadline, shardTimes;
        const GradingNow graded = shardGrading(shard, shardDeadline, shardTimes);
        if (shard == a.inputs.front())
            now = graded;
        else if (graded.rubricHash != now.rubricHash || graded.scenesHash != now.scenesHash ||
                 graded.maxScore != now.maxScore)
            throw InputError(
                shard + " was graded under another rubric, other scenes or another maximum than " +
                a.inputs.front() + ": grade them alike before merging");
        if (deadline.empty()) deadline = shardDeadline;
        if (times.empty()) times = shardTimes;
        for (const auto& entry : fs::directory_iterator(fs::path(shard) / "submissions")) {
            const std::string id = entry.path().filename().string();
            if (std::any_of(all.begin(), all.end(),
                            [&](const GradebookEntry& x) { return x.id == id; }))
                throw InputError("submission '" + id + "' is in more than one shard");
            all.push_back(readGradebookEntry(shard, id, ""));
        }
    }
    if (!deadline.empty()) {
        now.deadline = parseTime(deadline);
        if (!now.deadline)
            throw InputError("option --deadline: cannot read the time '" + deadline + "'");
    }
    if (!times.empty()) now.times = loadSubmissionTimes(times);
    const OutputLock lock(a.out, "grader batch or merge");
    fs::create_directories(a.out + "/submissions");
    for (const std::string& shard : a.inputs)
        if (fs::absolute(shard) != fs::absolute(a.out))
            for (const auto& entry : fs::directory_iterator(fs::path(shard) / "submissions"))
                fs::copy(entry.path(), fs::path(a.out) / "submissions" / entry.path().filename(),
                         fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    std::sort(all.begin(), all.end(),
              [](const GradebookEntry& x, const GradebookEntry& y) { return x.id < y.id; });
    std::vector<std::string> ids;
    for (const GradebookEntry& e : all) ids.push_back(e.id);
    const std::vector<SimilarLabs> similar = similarSubmissions(a.out, ids, a.prior);
    writeGradebook(a.out, all, now, similar);
    writeSideBySidePages(a.out, similarClusters(similar));
    std::printf("merged %zu submission(s) from %zu shard(s): %s/gradebook.csv\n", all.size(),
                a.inputs.size(), a.out.c_str());
    return 0;
}

} // namespace pathlab::grader
