// grader batch's choice of submissions: listed from the command line, then chosen by what
// their stored results say.
#include "commands/batch_selection.h"

#include "isolation/submission_intake.h"

#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pathlab::grader {

namespace fs = std::filesystem;

std::vector<Submission> listSubmissions(const Arguments& a) {
    std::vector<Submission> all;
    for (const std::string& input : a.inputs) {
        if (!fs::exists(input)) throw InputError(input + ": no such file or folder");
        if (!fs::is_directory(input)) {
            all.push_back({fs::absolute(input).string(), submissionId(input)});
            continue;
        }
        for (const auto& entry : fs::directory_iterator(input)) {
            const std::string name = entry.path().filename().string();
            if (name.empty() || name[0] == '.') continue;
            all.push_back(
                {fs::absolute(entry.path()).string(), submissionId(entry.path().string())});
        }
    }
    std::sort(all.begin(), all.end(),
              [](const Submission& x, const Submission& y) { return x.id < y.id; });
    for (size_t i = 1; i < all.size(); ++i)
        if (all[i].id == all[i - 1].id)
            throw InputError("two submissions have the id '" + all[i].id + "': " + all[i - 1].path +
                             " and " + all[i].path + " (rename one)");
    std::vector<Submission> shard;
    for (size_t i = 0; i < all.size(); ++i)
        if (static_cast<int>(i % a.shards) == a.shard) shard.push_back(all[i]);
    return shard;
}

bool hasId(const std::vector<Submission>& submissions, const std::string& id) {
    return std::any_of(submissions.begin(), submissions.end(),
                       [&](const Submission& s) { return s.id == id; });
}

void requireKnownIds(const std::vector<std::string>& only,
                     const std::vector<Submission>& submissions) {
    for (const std::string& id : only)
        if (!hasId(submissions, id))
            throw InputError("option --only: no submission has the id '" + id +
                             "' (gradebook.csv lists the ids)");
}

Selection selectSubmissions(const Arguments& a, const std::vector<Submission>& submissions,
                            const std::string& out, const GradingNow& grading,
                            const std::map<std::string, SubmittedFiles>& now) {
    Selection selection;
    for (const Submission& s : submissions) {
        const GradebookEntry stored = readGradebookEntry(out, s.id, s.path);
        const bool named = std::find(a.only.begin(), a.only.end(), s.id) != a.only.end();
        if (!a.only.empty()) {
            if (named)
                selection.todo.push_back(s);
            else
                ++selection.notNamed;
            continue;
        }
        if (a.force || stored.result.is_null()) {
            selection.todo.push_back(s);
            continue;
        }
        // A submission changed since it was graded is graded again, whatever else holds: its
        // old grade is not the grade of what it holds now.
        const nlohmann::json intake = stored.result.value("intake", nlohmann::json::object());
        const auto files = now.find(s.id);
        if (files != now.end() && (files->second.filesHash != intake.value("files_hash", "") ||
                                   files->second.commit != intake.value("commit", ""))) {
            selection.todo.push_back(s);
            selection.changed.push_back(s.id);
            continue;
        }
        const Regrade regrade = regradeNeeded(stored.result, grading);
        if (regrade == Regrade::None) {
            ++selection.current;
        } else if (a.keepStale) {
            ++selection.staleKept;
        } else if (regrade == Regrade::Rescore) {
            selection.rescore.push_back(s);
        } else {
            selection.todo.push_back(s);
            ++selection.staleRegraded;
        }
    }
    return selection;
}

void sayWhatIsKept(const Selection& selection) {
    if (selection.current > 0)
        std::fprintf(stderr, "%zu submission(s) already graded (--force grades them again)\n",
                     selection.current);
    if (selection.notNamed > 0)
        std::fprintf(stderr, "%zu submission(s) not named by --only: kept as they are\n",
                     selection.notNamed);
    if (selection.staleKept > 0)
        std::fprintf(stderr,
                     "%zu submission(s) graded under another rubric, other scenes or another "
                     "maximum (--no-speed): kept, marked stale in the gradebook\n",
                     selection.staleKept);
    if (selection.staleRegraded > 0)
        std::fprintf(stderr,
                     "%zu submission(s) graded on other scenes, by another kit or under a rubric "
                     "that measures otherwise (or without speed): graded again\n",
                     selection.staleRegraded);
    if (!selection.rescore.empty())
        std::fprintf(stderr,
                     "%zu submission(s) graded under other points or thresholds of the rubric: "
                     "judged again from their measurements, nothing rendered\n",
                     selection.rescore.size());
    for (const std::string& id : selection.changed)
        std::fprintf(stderr, "%s: changed since it was graded: graded again\n", id.c_str());
}

} // namespace pathlab::grader
