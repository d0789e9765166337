// grader batch: a class of submitted labs, graded in the sandbox (Linux only; batch_merge.cpp
// merges the gradebooks of batch shards anywhere).
//
// A batch grades each submission in a child `grader submission` process of its own, so one
// submission that breaks anything (the grader included) costs that submission only. Each writes
// its result.json last and atomically; a restarted batch skips those that have one.
//
// Fair timing while other work goes on: the first core the grader may use is kept for timed
// runs, taken by one grading at a time (an exclusive lock on /tmp/pathlab-timing-core-N.lock for
// a lab's whole interleaved series, one thread per timed render, shared by every batch on the
// machine); compiling and the correctness renders of every job share the other cores
// (batch_cores.h). The jobs are batch_jobs.h's, the canary that goes first batch_canary.h's.
#include "checks/student_variant.h"
#include "checks/grading_scenes.h"
#include "checks/scene_variants.h"
#include "checks/speed_check.h"
#include "commands/batch_canary.h"
#include "commands/batch_cores.h"
#include "commands/batch_estimate.h"
#include "commands/batch_jobs.h"
#include "commands/batch_selection.h"
#include "commands/commands.h"
#include "commands/grading_host.h"
#include "commands/output_lock.h"
#include "commands/rescore.h"
#include "commands/submission_grading.h"
#include "reports/gradebook.h"
#include "reports/lab_figures.h"
#include "reports/submission_time.h"
#include "similarity/class_similarity.h"
#include "similarity/side_by_side.h"

#include "pathlab/support/input_error.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/this_process.h"
#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// The options a child `grader submission` shares with the batch.
std::vector<std::string> sharedOptions(const Arguments& a) {
    std::vector<std::string> options = {"--rubric",     a.rubric,
                                        "--references", a.references,
                                        "--seed",       std::to_string(a.seed),
                                        "--scenes",     a.scenesDir.empty() ? "none" : a.scenesDir};
    if (a.revealHidden) options.push_back("--reveal-hidden");
    if (!a.speed) options.push_back("--no-speed");
    if (!a.raceCheck) options.push_back("--no-race-check");
    return options;
}

/// What a batch's gradebook is written against; stored in OUT/batch.json for `grader merge`.
/// `deadline` and `times` are the options', or those an earlier batch into OUT was given.
GradingNow gradingNow(const Arguments& a, const Rubric& rubric, const std::string& deadline,
                      const std::string& times) {
    GradingNow now;
    now.rubricHash = rubric.hash;
    now.measurementHash = rubric.measurementHash;
    now.measuresSpeed = a.speed;
    now.scenesHash = scenesHash(rubric, a.scenesDir);
    now.maxScore = maxScoreNow(rubric, a.speed);
    now.lowerScores = rubric.lowerScores;
    now.late = rubric.late;
    if (!deadline.empty()) {
        now.deadline = parseTime(deadline);
        if (!now.deadline)
            throw InputError("option --deadline expects a time like 2026-12-01T23:59 (local), "
                             "2026-12-01T23:59Z or 2026-12-01T23:59+01:00, got '" +
                             deadline + "'");
    }
    if (!times.empty()) now.times = loadSubmissionTimes(times);
    return now;
}

/// An earlier batch's setting in OUT/batch.json ("" if none).
std::string earlierSetting(const std::string& out, const char* key) {
    std::ifstream in(out + "/batch.json");
    const nlohmann::json j = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    return j.is_object() ? j.value(key, "") : "";
}

/// The deadline and the submission times (a CSV's path) a batch's gradebook is written against.
struct DeadlineAndTimes {
    std::string deadline, times;
};

/// A batch run again keeps the deadline and times it was given before, unless told others.
DeadlineAndTimes deadlineAndTimes(const Arguments& a, const std::string& out) {
    DeadlineAndTimes dates;
    dates.deadline = a.deadline.empty() ? earlierSetting(out, "deadline") : a.deadline;
    dates.times = a.times.empty() ? earlierSetting(out, "times") : fs::absolute(a.times).string();
    if (a.deadline.empty() && !dates.deadline.empty())
        std::fprintf(stderr, "deadline %s, as the batch before into %s (--deadline sets another)\n",
                     dates.deadline.c_str(), out.c_str());
    return dates;
}

/// A time for an id that is no submission is likely a typing error in the CSV (a shard, which
/// sees only some of the ids, cannot tell).
void noteTimesOfOthers(const GradingNow& grading, const std::vector<Submission>& submissions) {
    std::set<std::string> named;
    for (const auto& [id, when] : grading.times.whole) named.insert(id);
    for (const auto& [id, labs] : grading.times.byLab) named.insert(id);
    for (const std::string& id : named)
        if (!hasId(submissions, id))
            std::fprintf(stderr,
                         "note: the submission times name '%s', which is not a submission here\n",
                         id.c_str());
}

/// The batch's first line in batch.log: what it grades, and against what.
void logBatchStart(std::ofstream& log, const Arguments& a, size_t submissions,
                   const GradingNow& grading) {
    log << timestamp() << " batch of " << submissions << " submission(s), " << a.jobs << " job(s)"
        << (a.shards > 1 ? ", shard " + std::to_string(a.shard) + "/" + std::to_string(a.shards)
                         : "")
        << ", rubric " << grading.rubricHash << ", scenes " << grading.scenesHash << "\n";
}

/// A batch run again into OUT without --references grades against the references the batch
/// before used (its batch.json), as it keeps its deadline: a course rubric's references are not
/// the kit's, and the kit's would stop the batch as stale.
Arguments withEarlierReferences(Arguments a, const std::string& out) {
    a.references = fs::absolute(a.references).string();
    const std::string earlier = earlierSetting(out, "references");
    if (a.referencesGiven || earlier.empty() || earlier == a.references) return a;
    if (!fs::is_directory(earlier))
        throw InputError("the batch before into " + out + " graded against the references in " +
                         earlier + ", which is no longer a folder: pass --references");
    std::fprintf(stderr, "references %s, as the batch before into %s (--references sets others)\n",
                 earlier.c_str(), out.c_str());
    a.references = earlier;
    return a;
}

/// A batch into a folder graded under another rubric file, with no --rubric given, is most
/// likely an instructor who forgot it: re-scoring the class under the kit's rubric would change
/// every grade. It refuses, naming both files; with --rubric it goes on (a changed rubric is
/// re-scored or graded again, as the guide says).
void requireRubricOfEarlierBatch(const Arguments& a, const std::string& out,
                                 const GradingNow& grading) {
    std::ifstream in(out + "/batch.json");
    const nlohmann::json earlier =
        in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (!earlier.is_object() || a.rubricGiven) return;
    const std::string file = earlier.value("rubric_file", "");
    if (file.empty() || earlier.value("rubric_hash", "") == grading.rubricHash ||
        file == fs::absolute(a.rubric).string())
        return;
    throw InputError(out + " was graded under the rubric " + file +
                     " (its batch.json); without --rubric this batch would grade it again under "
                     "the kit's, " +
                     a.rubric + ". Pass --rubric " + file +
                     " to go on under that one, or --rubric with the kit's to change to it");
}

/// A batch.log whose last batch has no "batch finished" line: that batch was stopped (killed, a
/// reboot). Said once, when the next batch starts: what it graded is kept, the rest graded now.
void sayIfInterrupted(const std::string& out, std::ofstream& log) {
    std::ifstream in(out + "/batch.log");
    std::string line, lastStart;
    bool finished = true;
    while (std::getline(in, line)) {
        if (line.find(" batch of ") != std::string::npos) lastStart = line, finished = false;
        if (line.find(" batch finished") != std::string::npos ||
            line.find(" batch stopped") != std::string::npos)
            finished = true;
    }
    if (finished || lastStart.empty()) return;
    const std::string when = lastStart.substr(0, lastStart.find(' '));
    const std::string text = "the batch started at " + when +
                             " did not finish (interrupted): the submissions it graded are kept, "
                             "those it had not finished are graded now";
    std::fprintf(stderr, "%s\n", text.c_str());
    log << timestamp() << " " << text << "\n";
}

/// Writes "batch stopped" into the log when an error ends the batch, so that the next one does
/// not take it for interrupted.
struct LogsAnError {
    std::ofstream& log;
    ~LogsAnError() {
        if (std::uncaught_exceptions() > 0)
            log << timestamp() << " batch stopped by an error (told on the terminal)\n"
                << std::flush;
    }
};

/// Shared by every grading: the compiled kit, and the references of hidden scenes (kept with
/// this batch's output, measured again when a scene's files change).
struct SharedFiles {
    std::string kit, referenceCache;
};

/// Whether the gradings run the race check: said once for the batch, on standard error and in
/// its log, so that a grading told --no-race-check does not try again.
bool batchRaceCheck(const Arguments& a, bool anyToGrade, const LabBuild& build,
                    const std::vector<int>& workCpus, std::ofstream& log) {
    if (!a.raceCheck || !anyToGrade) return false;
    const RaceCheckRuntime runtime =
        raceCheckRuntime(build, {workCpus, sandboxUserForThisProcess()});
    const bool available = runtime.available();
    std::fprintf(stderr, "race check: %s\n",
                 available ? "each lab compiled with ThreadSanitizer and rendered with 2 threads"
                           : ("skipped, no lab fails for it: " + runtime.unavailable).c_str());
    log << timestamp() << " race check: " << (available ? "on" : "skipped: " + runtime.unavailable)
        << "\n";
    return available;
}

/// A child `grader submission`'s command line, but for the submission and its --out.
std::vector<std::string> childCommand(const Arguments& a, bool raceCheck, const SharedFiles& shared,
                                      const Cores& cores) {
    std::vector<std::string> argv = {thisProgram().string(), "submission"};
    std::vector<std::string> options = sharedOptions(a);
    if (a.raceCheck && !raceCheck) options.push_back("--no-race-check");
    argv.insert(argv.end(), options.begin(), options.end());
    argv.insert(argv.end(), {"--kit", shared.kit, "--timing-lock", timingLockFor(cores.timing),
                             "--timing-cpus", joinCpus(cores.timing), "--work-cpus",
                             joinCpus(cores.work), "--viewer", a.viewer, "--solution-viewer",
                             a.solutionViewer, "--reference-cache", shared.referenceCache});
    return argv;
}

/// The hidden scenes' references, measured into the batch's cache before the first job, so that
/// no job waits for them or measures them twice.
void measureHiddenReferences(const Arguments& a, const Rubric& rubric,
                             const std::string& referenceCache, const std::string& scratch) {
    std::vector<std::string> notes;
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    gradingScenes(rubric, {a.references, a.scenesDir, referenceCache, a.revealHidden}, solution,
                  scratch, notes);
}

/// Each student's own box (the rubric's per-student variants with a box scene), its reference
/// measured into the batch's cache before the first job, as the hidden scenes' are: the job
/// finds it there by its files, which are the same, written beside the student's feedback.
void measureStudentVariants(const Arguments& a, const Rubric& rubric,
                            const std::vector<Submission>& todo, const std::string& referenceCache,
                            const std::string& scratch) {
    if (!rubric.variants.perStudent || rubric.variants.boxScene.empty()) return;
    const std::string secret = classSecret(rubric.variants);
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    // One reference per student, before the first grading and before the gradings' estimate:
    // a class of 200 takes a while here, so the first one measured says how long.
    std::fprintf(stderr,
                 "the box references of %zu student(s)' variants, each measured once and then "
                 "kept ...\n",
                 todo.size());
    bool estimated = false;
    for (size_t i = 0; i < todo.size(); ++i) {
        const auto start = std::chrono::steady_clock::now();
        const std::string folder = scratch + "/variants/" + todo[i].id;
        studentVariantScenes(rubric, drawStudentVariant(rubric.variants, secret, todo[i].id),
                             folder, solution, scratch, referenceCache);
        fs::remove_all(folder);
        const double seconds = secondsSince(start);
        if (!estimated && seconds > 1 && i + 1 < todo.size()) {
            estimated = true;
            std::fprintf(stderr,
                         "estimated: a box reference took %.1f s; at most %s for the other %zu "
                         "student(s)\n",
                         seconds, roughDuration(seconds * (todo.size() - i - 1)).c_str(),
                         todo.size() - i - 1);
        }
    }
}

/// OUT/batch.json: what the batch's gradebook is written against, for `grader merge` and for
/// the next batch into OUT.
void writeBatchJson(const std::string& out, const std::string& rubricFile,
                    const std::string& references, const GradingNow& grading,
                    const DeadlineAndTimes& dates) {
    writeFileAtomically(out + "/batch.json",
                        nlohmann::json{{"rubric_file", rubricFile},
                                       {"references", references},
                                       {"rubric_hash", grading.rubricHash},
                                       {"scenes_hash", grading.scenesHash},
                                       {"max_score", grading.maxScore},
                                       {"deadline", dates.deadline},
                                       {"times", dates.times},
                                       {"lower_scores", lowerScoresName(grading.lowerScores)},
                                       {"late", latePolicyJson(grading.late)}}
                                .dump(1) +
                            "\n");
}

/// Each graded submission's lab files as they are now, taken in as a grading takes them, so
/// that one changed since it was graded is graded again.
std::map<std::string, SubmittedFiles> submittedFiles(const std::vector<Submission>& submissions,
                                                     const std::string& out,
                                                     const SandboxPolicy& policy,
                                                     const std::string& scratch) {
    const auto start = std::chrono::steady_clock::now();
    std::map<std::string, SubmittedFiles> files;
    for (const Submission& s : submissions) {
        if (!fs::exists(out + "/submissions/" + s.id + "/result.json")) continue;
        const std::string folder = scratch + "/intake-" + s.id;
        fs::remove_all(folder);
        fs::create_directories(folder);
        fs::permissions(folder, fs::perms::owner_all | fs::perms::others_read |
                                    fs::perms::others_exec | fs::perms::group_read |
                                    fs::perms::group_exec);
        const Intake intake = takeSubmission(s.path, folder, policy);
        files[s.id] = {labFilesHash(intake, folder), intake.commit};
        fs::remove_all(folder);
    }
    if (!files.empty())
        std::fprintf(stderr, "checked %zu graded submission(s) for changes in %.0f s\n",
                     files.size(), secondsSince(start));
    return files;
}

/// Judges again, from their measurements, the submissions whose rubric changed only in points
/// or thresholds; returns those that kept none to judge (graded again instead).
std::vector<Submission> rescoreAll(const Arguments& a, const Rubric& rubric,
                                   const std::vector<Submission>& rescore, const std::string& out,
                                   std::ofstream& log) {
    std::vector<Submission> measureInstead;
    for (const Submission& s : rescore) {
        const Rescore r =
            rescoreSubmission(rubric, a.speed, a.references, s, out + "/submissions/" + s.id);
        if (!r.done) {
            measureInstead.push_back(s);
            continue;
        }
        char line[256];
        std::snprintf(line, sizeof line,
                      "%s: re-scored from attempt %d's measurements: %g / %g -> %g / %g",
                      s.id.c_str(), r.fromAttempt, r.before, r.maxBefore, r.after, r.maxAfter);
        std::fprintf(stderr, "%s\n", line);
        log << timestamp() << " " << line << "\n" << std::flush;
    }
    return measureInstead;
}

/// The batch's arguments with its hidden scenes settled: the instructor's where there are any;
/// else (unless --scenes none, or the rubric's hidden_scenes.variants is 0) the rubric's variants
/// of the public scenes, written into OUT/.variants from the seed kept there (scene_variants.h).
Arguments withHiddenScenes(const Arguments& a, const Rubric& rubric, const std::string& out) {
    if (!a.scenesDir.empty() || a.scenesNone || rubric.sceneVariants <= 0) return a;
    Arguments graded = a;
    graded.scenesDir = out + "/.variants";
    const std::string seedFile = graded.scenesDir + "/seed";
    const uint64_t seed = variantSeed(a, seedFile);
    if (writeSceneVariants(rubric, graded.scenesDir, seed).empty()) {
        std::fprintf(stderr, "hidden scenes: none kept, and the rubric's public scenes are all "
                             "furnaces, of which no variant is made (hidden_scenes.variants): "
                             "graded on the public scenes only\n");
        return a;
    }
    writeFileAtomically(seedFile, std::to_string(seed) + "\n");
    std::fprintf(stderr,
                 "hidden scenes: none kept, so %d variant(s) of the public scenes, made from the "
                 "seed in %s (the rubric's hidden_scenes.variants; --scenes none grades on the "
                 "public scenes only)\n",
                 rubric.sceneVariants, seedFile.c_str());
    return graded;
}

/// The Slurm array the estimate is given for: --estimate-nodes, PATHLAB_CPUS cores each (what
/// grade-class.sh asks for).
SlurmArray slurmArray(const Arguments& a) {
    SlurmArray array;
    array.nodes = a.estimateNodes;
    if (const char* cpus = std::getenv("PATHLAB_CPUS"); cpus && std::atoi(cpus) > 0)
        array.cpusPerNode = std::atoi(cpus);
    return array;
}

/// Before the first grading: how long the gradings will take, on the terminal and in batch.log;
/// the figure it rests on, for the measured one at the end. None before anything was measured
/// here (a first batch whose canary was skipped cannot be: its canary always runs).
std::optional<GradingTime> sayEstimate(const Arguments& a, const std::string& out, size_t count,
                                       std::ofstream& log) {
    if (count == 0) return std::nullopt;
    const std::optional<GradingTime> time = measuredGradingTime(out, a.speed);
    if (!time) return std::nullopt;
    const std::string text = batchEstimate(*time, count, a.jobs, slurmArray(a));
    std::fputs(text.c_str(), stderr);
    log << timestamp() << " " << text;
    return time;
}

/// What this batch's gradings changed for the submissions graded before: a line each on the
/// terminal and in batch.log (regrades.csv and summary.html have every submission's last), and
/// what the gradebook does with the totals a regrade lowered.
void reportRegrades(const std::string& out, const std::vector<Submission>& gradedNow,
                    const GradingNow& grading, std::ofstream& log) {
    int lowered = 0;
    for (const Submission& s : gradedNow) {
        const GradebookEntry e = readGradebookEntry(out, s.id, s.path);
        if (e.result.is_null()) continue;
        const std::optional<RegradeComparison> c =
            compareWithAttemptBefore(s.id, out + "/submissions/" + s.id, e.result);
        if (!c) continue;
        const std::string line = "regrade " + regradeLine(*c);
        std::fprintf(stderr, "%s\n", line.c_str());
        log << timestamp() << " " << line << "\n";
        lowered += e.higherEarlier.has_value();
    }
    if (lowered == 0) return;
    const std::string text =
        std::to_string(lowered) + " total(s) lowered by a regrade of the same files: " +
        (grading.lowerScores == LowerScores::Replace
             ? "the lower totals count (the rubric's regrades.lower_scores: replace)"
         : grading.lowerScores == LowerScores::KeepHigher
             ? "the higher earlier totals count (the rubric's regrades.lower_scores: keep_higher)"
             : "withheld from lms.csv until the rubric says which counts: regrades.lower_scores "
               "\"replace\" (the lower total) or \"keep_higher\" (the higher earlier one); "
               "setting it re-grades nothing");
    std::fprintf(stderr, "%s\n", text.c_str());
    log << timestamp() << " " << text << "\n";
}

} // namespace

int runBatch(const Arguments& given, const Rubric& rubric, const std::string& scratch) {
    requireSandbox();
    const OutputLock lock(given.out, "grader batch");
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Submission> submissions = listSubmissions(given);
    requireKnownIds(given.only, submissions);
    fs::create_directories(given.out + "/submissions");
    const std::string out = fs::absolute(given.out).string();
    const Arguments a = withEarlierReferences(withHiddenScenes(given, rubric, out), out);
    const DeadlineAndTimes dates = deadlineAndTimes(a, out);
    const GradingNow grading = gradingNow(a, rubric, dates.deadline, dates.times);
    if (a.shards == 1) noteTimesOfOthers(grading, submissions);
    requireRubricOfEarlierBatch(a, out, grading);
    std::ofstream log(out + "/batch.log", std::ios::app);
    sayIfInterrupted(out, log);
    logBatchStart(log, a, submissions.size(), grading);
    const LogsAnError logsAnError{log};
    const bool askAboutChanges = a.only.empty() && !a.force;
    const std::map<std::string, SubmittedFiles> files =
        askAboutChanges
            ? submittedFiles(submissions, out, {{}, sandboxUserForThisProcess()}, scratch)
            : std::map<std::string, SubmittedFiles>{};
    Selection selection = selectSubmissions(a, submissions, out, grading, files);
    const Cores cores = splitCores(allowedCpus());
    const LabBuild build = labBuildOfThisGrader();
    const SharedFiles shared{out + "/.kit", out + "/.references"};
    // What a grading needs, made once, when a grading is to run at all (a batch that only
    // re-scores needs none of it): whether the race check runs, the gradings' command line,
    // the compiled kit and the hidden scenes' references.
    std::vector<std::string> childBase;
    const auto prepare = [&] {
        if (!childBase.empty()) return;
        const bool raceCheck = batchRaceCheck(a, true, build, cores.work, log);
        childBase = childCommand(a, raceCheck, shared, cores);
        std::fprintf(stderr, "compiling the lab kit (stubs, table, reference solutions) ...\n");
        buildLabKit(build, shared.kit, {cores.work, sandboxUserForThisProcess()});
        measureHiddenReferences(a, rubric, shared.referenceCache, scratch);
        measureStudentVariants(a, rubric, selection.todo, shared.referenceCache, scratch);
    };
    if (!selection.todo.empty() || !selection.rescore.empty())
        runCanary(childBase, build.solutions, out, grading, rubric, a.references, prepare, log);
    sayWhatIsKept(selection); // once the scenes' references and the canary let the batch go on
    const std::vector<Submission> unmeasured = rescoreAll(a, rubric, selection.rescore, out, log);
    const size_t rescored = selection.rescore.size() - unmeasured.size();
    selection.todo.insert(selection.todo.end(), unmeasured.begin(), unmeasured.end());
    if (!selection.todo.empty()) prepare();
    // What this batch's gradebook is written against, for `grader merge`: only once the canary
    // passed, so that a batch it stopped changes nothing.
    writeBatchJson(out, fs::absolute(a.rubric).string(), a.references, grading, dates);
    const std::optional<GradingTime> estimated = sayEstimate(a, out, selection.todo.size(), log);
    const auto gradingsStart = std::chrono::steady_clock::now();
    const JobCounts counts =
        gradeInJobs(a.jobs, childBase, selection.todo, submissions, out, grading, log);
    const double gradingSeconds = secondsSince(gradingsStart); // the similarity report apart
    const std::vector<SimilarLabs> similar = similarSubmissions(out, idsOf(submissions), a.prior);
    writeGradebook(out, gradebookEntries(out, submissions, {}), grading, similar);
    writeSideBySidePages(out, similarClusters(similar));
    std::vector<Submission> gradedNow = selection.todo;
    for (const Submission& s : selection.rescore)
        if (std::none_of(unmeasured.begin(), unmeasured.end(),
                         [&](const Submission& u) { return u.id == s.id; }))
            gradedNow.push_back(s);
    reportRegrades(out, gradedNow, grading, log);
    const double seconds = secondsSince(start);
    log << timestamp() << " batch finished in " << seconds << " s\n";
    if (estimated && counts.done > 0) {
        const std::string text =
            "measured: " + std::to_string(counts.done) + " submission(s) graded in " +
            roughDuration(gradingSeconds) + ", " + std::to_string(a.jobs) +
            " at a time (estimated " +
            roughDuration(batchSeconds(*estimated, selection.todo.size(), a.jobs)) + ")";
        std::fprintf(stderr, "%s\n", text.c_str());
        log << timestamp() << " " << text << "\n";
    }
    std::printf("graded %zu submission(s) and re-scored %zu in %.0f s (%zu kept as they were, %zu "
                "not graded, %zu similar pair(s)): %s/gradebook.csv, %s/lms.csv, %s/summary.html\n",
                counts.done - counts.failed, rescored, seconds,
                submissions.size() - selection.todo.size() - rescored, counts.failed,
                similar.size(), out.c_str(), out.c_str(), out.c_str());
    return 0;
}

} // namespace pathlab::grader
