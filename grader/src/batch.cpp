// grader submission / batch: submitted labs, graded in the sandbox (Linux only; batch_merge.cpp
// merges the gradebooks of batch shards anywhere).
//
// A batch grades each submission in a child `grader submission` process of its own, so one
// submission that breaks anything (the grader included) costs that submission only. Each writes
// its result.json last and atomically; a restarted batch skips those that have one.
//
// Fair timing while other work goes on: the first core the grader may use is kept for timed
// runs, taken by one grading at a time (an exclusive lock on OUT/.timing.lock for a lab's whole
// interleaved series, one thread per timed render); compiling and the correctness renders of
// every job share the other cores.
#include "commands.h"
#include "gradebook.h"
#include "grading_scenes.h"
#include "lab_figures.h"
#include "progress_bar.h"
#include "submission_grading.h"
#include "time_limit.h"

#include "pathlab/input_error.h"
#include "pathlab/render_stats.h"
#include "pathlab/this_process.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

LabBuild labBuildOfThisGrader() {
    return loadLabBuild((thisProgram().parent_path() / "lab_library_build.json").string());
}

/// The reference's start-up when the references were made; 0 if they hold none.
double storedStartUpSeconds(const Arguments& a, const Rubric& rubric) {
    try {
        return loadLabFigures(a.references + "/lab_figures.json", rubric).startUpSeconds;
    } catch (const InputError&) {
        return 0;
    }
}

void requireSandbox() {
    const std::string reason = sandboxUnavailableReason();
    if (!reason.empty()) throw InputError("the sandbox: " + reason);
}

/// The cores this process may use, in order.
std::vector<int> allowedCpus() {
    cpu_set_t set;
    std::vector<int> cpus;
    if (::sched_getaffinity(0, sizeof set, &set) == 0)
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
    return cpus;
}

std::string joinCpus(const std::vector<int>& cpus) {
    std::string text;
    for (int cpu : cpus) text += (text.empty() ? "" : ",") + std::to_string(cpu);
    return text;
}

std::string timestamp() {
    char text[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", std::localtime(&now));
    return text;
}

struct Submission {
    std::string path, id;
};

/// The submissions named on the command line: each folder's entries (a folder of
/// submissions), or a .zip/.tar.gz given directly; sorted by id, this shard's only.
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
            all.push_back({fs::absolute(entry.path()).string(), submissionId(entry.path().string())});
        }
    }
    std::sort(all.begin(), all.end(), [](const Submission& x, const Submission& y) { return x.id < y.id; });
    for (size_t i = 1; i < all.size(); ++i)
        if (all[i].id == all[i - 1].id)
            throw InputError("two submissions have the id '" + all[i].id + "': " + all[i - 1].path +
                             " and " + all[i].path + " (rename one)");
    std::vector<Submission> shard;
    for (size_t i = 0; i < all.size(); ++i)
        if (static_cast<int>(i % a.shards) == a.shard) shard.push_back(all[i]);
    return shard;
}

/// The options a child `grader submission` shares with the batch.
std::vector<std::string> sharedOptions(const Arguments& a) {
    std::vector<std::string> options = {"--rubric", a.rubric, "--references", a.references,
                                        "--seed", std::to_string(a.seed)};
    if (!a.scenesDir.empty()) options.insert(options.end(), {"--scenes", a.scenesDir});
    if (!a.speed) options.push_back("--no-speed");
    return options;
}

/// A child grading one submission.
struct Job {
    pid_t pid = -1;
    Submission submission;
    std::chrono::steady_clock::time_point start;
};

Job startJob(const std::vector<std::string>& argv, const Submission& s, const std::string& log) {
    Job job{-1, s, std::chrono::steady_clock::now()};
    job.pid = ::fork();
    if (job.pid == 0) {
        ::prctl(PR_SET_PDEATHSIG, SIGKILL); // a killed batch leaves no grading behind
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd >= 0) ::dup2(fd, STDOUT_FILENO), ::dup2(fd, STDERR_FILENO);
        std::vector<char*> args;
        for (const std::string& arg : argv) args.push_back(const_cast<char*>(arg.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    return job;
}

} // namespace

int gradeOneSubmission(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    requireSandbox();
    fs::create_directories(a.out);
    SubmissionGrader g;
    g.build = labBuildOfThisGrader();
    g.rubric = rubric;
    g.workCpus = a.workCpus;
    g.kit = a.kit.empty() ? buildLabKit(g.build, a.out + "/kit", {a.workCpus, sandboxUserForThisProcess()})
                          : existingLabKit(a.kit);
    // References of hidden scenes come from the solutions, linked into this build's viewer.
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    std::vector<std::string> notes;
    g.scenes = gradingScenes(rubric, a.references, a.scenesDir, a.referenceCache, solution, scratch, notes);
    g.timing = {a.timingCpus, a.timingLock, a.timingCpus.empty() ? 0 : 1};
    g.threads = a.workCpus.empty() ? a.threads : static_cast<int>(a.workCpus.size());
    g.seedBase = a.seed;
    g.measureSpeed = a.speed;
    // The time limits, scaled to this machine's speed now: the solutions' start-up timed as it
    // was when the references were made (outside the sandbox, on every core).
    GraderSetup probe;
    probe.rubric = rubric;
    probe.scratch = scratch;
    probe.threads = a.threads;
    g.runSeconds = scaledTimeLimit(rubric.secondsPerRun, speedSceneStartUpSeconds(probe, solution),
                                   storedStartUpSeconds(a, rubric));
    if (g.runSeconds > rubric.secondsPerRun)
        notes.push_back(timeLimitNote(rubric.secondsPerRun, g.runSeconds));
    SubmissionOutcome outcome = gradeSubmission(g, a.inputs[0], a.out);
    outcome.report.notes.insert(outcome.report.notes.begin(), notes.begin(), notes.end());
    std::printf("%s: %s\n", outcome.id.c_str(), outcome.status.c_str());
    std::fputs(terminalReport(outcome.report, false).c_str(), stdout);
    writeReports(a, outcome.report);
    return 0;
}

int runBatch(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    requireSandbox();
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Submission> submissions = listSubmissions(a);
    fs::create_directories(a.out + "/submissions");
    const std::string out = fs::absolute(a.out).string();
    std::ofstream log(out + "/batch.log", std::ios::app);
    log << timestamp() << " batch of " << submissions.size() << " submission(s), " << a.jobs << " job(s)"
        << (a.shards > 1 ? ", shard " + std::to_string(a.shard) + "/" + std::to_string(a.shards) : "") << "\n";

    // Cores: the first for timed runs, the rest for everything else.
    const std::vector<int> cpus = allowedCpus();
    const std::vector<int> timingCpus = cpus.empty() ? std::vector<int>{} : std::vector<int>{cpus[0]};
    const std::vector<int> workCpus = cpus.size() > 1 ? std::vector<int>(cpus.begin() + 1, cpus.end()) : cpus;

    // Shared by every grading: the compiled kit, and the references of hidden scenes.
    const LabBuild build = labBuildOfThisGrader();
    const std::string kit = out + "/.kit";
    std::fprintf(stderr, "compiling the lab kit (stubs, table, reference solutions) ...\n");
    buildLabKit(build, kit, {workCpus, sandboxUserForThisProcess()});
    const std::string referenceCache = out + "/.references";
    if (!a.scenesDir.empty()) {
        std::vector<std::string> notes;
        const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
        gradingScenes(rubric, a.references, a.scenesDir, referenceCache, solution, scratch, notes);
    }

    std::vector<Submission> todo;
    for (const Submission& s : submissions)
        if (a.force || !fs::exists(out + "/submissions/" + s.id + "/result.json")) todo.push_back(s);
    const size_t skipped = submissions.size() - todo.size();
    if (skipped > 0)
        std::fprintf(stderr, "%zu submission(s) already graded (--force grades them again)\n", skipped);

    const std::vector<std::string> childBase = [&] {
        std::vector<std::string> argv = {thisProgram().string(), "submission"};
        const std::vector<std::string> shared = sharedOptions(a);
        argv.insert(argv.end(), shared.begin(), shared.end());
        argv.insert(argv.end(), {"--kit", kit, "--timing-lock", out + "/.timing.lock",
                                 "--timing-cpus", joinCpus(timingCpus), "--work-cpus", joinCpus(workCpus),
                                 "--viewer", a.viewer, "--solution-viewer", a.solutionViewer});
        if (!a.scenesDir.empty()) argv.insert(argv.end(), {"--reference-cache", referenceCache});
        return argv;
    }();
    auto entries = [&] {
        std::vector<GradebookEntry> list;
        for (const Submission& s : submissions) list.push_back(readGradebookEntry(out, s.id, s.path));
        return list;
    };

    ProgressBar progress("grading", "submissions");
    const double jobSeconds = 3600; // far beyond any grading: only a grader fault gets here
    std::vector<Job> running;
    size_t next = 0, done = 0, failed = 0;
    progress.update(0, static_cast<int>(todo.size()));
    while (next < todo.size() || !running.empty()) {
        while (next < todo.size() && static_cast<int>(running.size()) < a.jobs) {
            const Submission& s = todo[next++];
            const std::string folder = out + "/submissions/" + s.id;
            fs::remove(folder + "/result.json");
            fs::create_directories(folder);
            std::vector<std::string> argv = childBase;
            argv.insert(argv.end(), {s.path, "--out", folder});
            running.push_back(startJob(argv, s, folder + "/grader.log"));
            log << timestamp() << " start " << s.id << " (" << s.path << ")\n" << std::flush;
        }
        int status = 0;
        const pid_t ended = ::waitpid(-1, &status, WNOHANG);
        const auto now = std::chrono::steady_clock::now();
        for (Job& job : running)
            if (job.pid != ended && std::chrono::duration<double>(now - job.start).count() > jobSeconds)
                ::kill(job.pid, SIGKILL); // reaped below on a later turn
        const auto job = std::find_if(running.begin(), running.end(), [&](const Job& j) { return j.pid == ended; });
        if (ended <= 0 || job == running.end()) {
            ::usleep(50000);
            continue;
        }
        const GradebookEntry entry = readGradebookEntry(out, job->submission.id, job->submission.path);
        const double seconds = std::chrono::duration<double>(now - job->start).count();
        ++done;
        if (entry.result.is_null()) ++failed;
        log << timestamp() << " done " << job->submission.id << ": ";
        if (entry.result.is_null())
            log << "not graded, " << entry.problem;
        else
            log << entry.result.value("status", "") << ", " << entry.result.value("score", 0.0)
                << " / " << entry.result.value("max_score", 0.0);
        log << ", " << std::lround(seconds) << " s\n" << std::flush;
        running.erase(job);
        writeGradebook(out, entries());
        progress.update(static_cast<int>(done), static_cast<int>(todo.size()),
                        failed > 0 ? std::to_string(failed) + " not graded" : "");
    }
    writeGradebook(out, entries());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log << timestamp() << " batch finished in " << seconds << " s\n";
    std::printf("graded %zu submission(s) in %.0f s (%zu skipped, %zu not graded): %s/gradebook.csv, "
                "%s/summary.html\n", done - failed, seconds, skipped, failed, out.c_str(), out.c_str());
    return 0;
}

} // namespace pathlab::grader
