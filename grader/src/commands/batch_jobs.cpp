#include "commands/batch_jobs.h"

#include "commands/submission_grading.h"
#include "common/local_time.h"

#include "pathlab/support/progress_bar.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <unistd.h>

namespace pathlab::grader {

namespace fs = std::filesystem;

namespace {

/// Starts grading `s` into OUT/submissions/ID; its earlier grading goes first, kept as an
/// attempt, since a job's result.json is the sign that it is done.
Job startGrading(const std::vector<std::string>& childBase, const Submission& s,
                 const std::string& out, std::ofstream& log) {
    const std::string folder = out + "/submissions/" + s.id;
    fs::create_directories(folder);
    archiveAttempt(folder);
    std::vector<std::string> argv = childBase;
    argv.insert(argv.end(), {s.path, "--out", folder});
    Job job = startJob(argv, s, folder + "/grader.log");
    log << timestamp() << " start " << s.id << " (" << s.path << ")\n" << std::flush;
    return job;
}

/// A job still running after far longer than any grading takes has hit a grader fault.
void killOverdue(std::vector<Job>& running, std::chrono::steady_clock::time_point now) {
    const double jobSeconds = 3600; // far beyond any grading: only a grader fault gets here
    for (Job& j : running)
        if (std::chrono::duration<double>(now - j.start).count() > jobSeconds)
            j.child.kill(); // reaped on a later turn (nothing if it already has been)
}

/// A job's end in the batch's log: its status and score, or why it was not graded, its time and
/// where that went.
void logJobEnd(std::ofstream& log, const Job& job, const GradebookEntry& entry, double seconds) {
    log << timestamp() << " done " << job.submission.id << ": ";
    if (entry.result.is_null())
        log << "not graded, " << entry.problem;
    else
        log << entry.result.value("status", "") << ", " << entry.result.value("score", 0.0) << " / "
            << entry.result.value("max_score", 0.0);
    log << ", " << std::lround(seconds) << " s";
    const nlohmann::json phases = entry.result.is_null()
                                      ? nlohmann::json()
                                      : entry.result.value("seconds_by_phase", nlohmann::json());
    if (phases.is_object()) {
        log << " (";
        for (const char* phase : {"intake", "compile", "correctness", "race_check", "speed"}) {
            char text[64];
            std::snprintf(text, sizeof text, "%s%s %.1f s", phase[0] == 'i' ? "" : ", ", phase,
                          phases.value(phase, 0.0));
            log << text;
        }
        log << ")";
    }
    log << "\n" << std::flush;
}

} // namespace

std::string timestamp() { return localTimeNow(); }

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::string> idsOf(const std::vector<Submission>& submissions) {
    std::vector<std::string> ids;
    for (const Submission& s : submissions) ids.push_back(s.id);
    return ids;
}

Job startJob(const std::vector<std::string>& argv, const Submission& s, const std::string& log) {
    ChildSetup setup;
    setup.dieWithParent = true; // a killed batch leaves no grading behind
    setup.outputFile = log;
    return {ChildProcess(argv, setup), s, std::chrono::steady_clock::now()};
}

std::vector<GradebookEntry> gradebookEntries(const std::string& out,
                                             const std::vector<Submission>& submissions,
                                             const std::vector<std::string>& queued) {
    std::vector<GradebookEntry> list;
    for (const Submission& s : submissions) {
        list.push_back(readGradebookEntry(out, s.id, s.path));
        list.back().pending = std::find(queued.begin(), queued.end(), s.id) != queued.end();
    }
    return list;
}

JobCounts gradeInJobs(int jobs, const std::vector<std::string>& childBase,
                      const std::vector<Submission>& todo,
                      const std::vector<Submission>& submissions, const std::string& out,
                      const GradingNow& grading, std::ofstream& log) {
    std::vector<std::string> queued = idsOf(todo);
    writeGradebook(out, gradebookEntries(out, submissions, queued), grading, std::nullopt);
    JobCounts counts;
    if (todo.empty()) return counts; // no progress bar counting to 0 of 0
    ProgressBar progress("grading", "submissions");
    std::vector<Job> running;
    size_t next = 0;
    progress.update(0, static_cast<int>(todo.size()));
    while (next < todo.size() || !running.empty()) {
        while (next < todo.size() && static_cast<int>(running.size()) < jobs)
            running.push_back(startGrading(childBase, todo[next++], out, log));
        // The first job found to have ended, reaped; the others on later turns.
        const auto job =
            std::find_if(running.begin(), running.end(), [](Job& j) { return j.child.poll(); });
        const auto now = std::chrono::steady_clock::now();
        killOverdue(running, now);
        if (job == running.end()) {
            ::usleep(50000);
            continue;
        }
        queued.erase(std::find(queued.begin(), queued.end(), job->submission.id));
        const GradebookEntry entry =
            readGradebookEntry(out, job->submission.id, job->submission.path);
        ++counts.done;
        if (entry.result.is_null()) ++counts.failed;
        logJobEnd(log, *job, entry, std::chrono::duration<double>(now - job->start).count());
        running.erase(job);
        writeGradebook(out, gradebookEntries(out, submissions, queued), grading, std::nullopt);
        progress.update(static_cast<int>(counts.done), static_cast<int>(todo.size()),
                        counts.failed > 0 ? std::to_string(counts.failed) + " not graded" : "");
    }
    return counts;
}

} // namespace pathlab::grader
