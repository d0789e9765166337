#include "commands/submission_grading.h"

#include "commands/grade_lab.h"
#include "common/content_hash.h"
#include "reports/reports.h"
#include "reports/submission_time.h"

#include "pathlab/render/render_stats.h"
#include "pathlab/support/printable_text.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace {

namespace fs = std::filesystem;

/// A folder the sandbox's unprivileged user can read (its files are bound into sandboxes).
void makeReadableFolder(const std::string& folder) {
    fs::create_directories(folder);
    fs::permissions(folder, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
}

/// The race check of one submission's labs, each logged with its time on standard error.
std::function<RaceFinding(Lab)> raceCheckOf(const SubmissionGrader& grader,
                                            const std::string& sources, const std::string& build,
                                            const SandboxPolicy& policy, const std::string& id) {
    const RaceCheckRun races{grader.build, grader.kit, grader.raceCheck, sources,
                             build,        policy,     grader.seedBase};
    return [races, id](Lab lab) {
        const RaceFinding finding = checkRaces(races, lab);
        std::fprintf(stderr, "%s: %s: race check, %.1f s\n", id.c_str(),
                     std::string(labName(lab)).c_str(), finding.seconds);
        return finding;
    };
}

/// The checks' setup for one submission: its own labs' libraries against the kit's reference
/// solutions, both run in the sandbox.
GraderSetup setupFor(const SubmissionGrader& grader, const SubmissionLibrary& library,
                     const SandboxPolicy& policy, const std::string& scratch) {
    GraderSetup setup;
    setup.student = {grader.build.viewer, Implementation::Student, library.library, policy, {}};
    // The solutions' one library holds every lab.
    ByLab<std::string> solutions;
    for (Lab lab : AllLabs) solutions[lab] = grader.kit.solutionsLibrary;
    setup.solution = {grader.build.viewer, Implementation::Student, solutions, policy, {}};
    setup.timing = grader.timing;
    setup.rubric = grader.rubric;
    setup.scenes = grader.scenes;
    setup.scratch = scratch;
    setup.seedBase = grader.seedBase;
    setup.threads = grader.threads;
    setup.measureSpeed = grader.measureSpeed;
    return setup;
}

/// The status names labs in a list with spaces between: `lab` added at its end.
void addLabName(std::string& names, Lab lab) {
    names += (names.empty() ? "" : " ") + std::string(labName(lab));
}

/// Measures each lab that compiled and linked, and the others as ungraded with the reason, into
/// `outcome`'s measurements; returns the submission's status: graded, and which labs were not
/// submitted, do not compile or do not link.
std::string measureLabs(const SubmissionGrader& grader, const SubmissionLibrary& library,
                        const GraderSetup& setup, SubmissionOutcome& outcome) {
    StartUpTimes startUps;        // this submission's: its labs' libraries are its own
    std::string broken, unlinked; // names of the labs that do not compile, do not link
    for (Lab lab : AllLabs) {
        const LabCompilation& compiled = library.labs[lab];
        LabMeasurement ungraded;
        ungraded.lab = lab;
        ungraded.speedMeasured = grader.measureSpeed;
        if (compiled.status == LabCompilation::Status::NotSubmitted) {
            ungraded.ungraded = "not submitted";
        } else if (compiled.status == LabCompilation::Status::Failed) {
            addLabName(broken, lab);
            ungraded.ungraded = "does not compile";
            ungraded.ungradedDetails = {compiled.messages};
        } else if (!library.linked(lab)) {
            addLabName(unlinked, lab);
            ungraded.ungraded = "does not link";
            ungraded.ungradedDetails = {library.problem[lab]};
        }
        outcome.measurements.push_back(ungraded.ungraded.empty() ? measureLab(setup, lab, startUps)
                                                                 : ungraded);
        const PhaseSeconds& spent = outcome.measurements.back().seconds;
        outcome.seconds.labs.correctness += spent.correctness;
        outcome.seconds.labs.race += spent.race;
        outcome.seconds.labs.speed += spent.speed;
    }
    std::string status = "graded";
    std::string missing;
    for (Lab lab : AllLabs)
        if (library.labs[lab].status == LabCompilation::Status::NotSubmitted)
            addLabName(missing, lab);
    if (!missing.empty()) status += "; not submitted: " + missing;
    if (!broken.empty()) status += "; does not compile: " + broken;
    if (!unlinked.empty()) status += "; does not link: " + unlinked;
    return status;
}

/// Wall-clock seconds since `start`.
double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The files of one grading, in the order an attempt is archived.
const char* const GradingFiles[] = {"result.json", "feedback.json", "measurements.json",
                                    "index.html",  "grader.log",    "pictures"};

/// The earlier attempts kept in FOLDER/attempts/, by number.
std::vector<GradeReport::Attempt> earlierAttempts(const std::string& folder) {
    std::vector<GradeReport::Attempt> attempts;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder + "/attempts", error)) {
        std::ifstream in(entry.path() / "result.json");
        const nlohmann::json r = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
        if (!r.is_object()) continue;
        attempts.push_back({r.value("attempt", 0), r.value("score", 0.0), r.value("max_score", 0.0),
                            r.value("graded_at", ""), r.value("how", "graded")});
    }
    std::sort(attempts.begin(), attempts.end(),
              [](const auto& x, const auto& y) { return x.number < y.number; });
    return attempts;
}

} // namespace

std::string labFilesHash(const Intake& intake, const std::string& folder) {
    ContentHash files;
    for (const auto& [name, where] : intake.taken) files.add(name).addFile(folder + "/" + name);
    return files.hex();
}

int archiveAttempt(const std::string& folder) {
    int highest = 0;
    for (const GradeReport::Attempt& a : earlierAttempts(folder))
        highest = std::max(highest, a.number);
    std::ifstream in(folder + "/result.json");
    const nlohmann::json current =
        in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    in.close();
    if (!current.is_object()) return highest + 1;
    const int number = std::max(current.value("attempt", 1), highest + 1);
    const std::string kept = folder + "/attempts/" + std::to_string(number);
    fs::create_directories(kept);
    for (const char* name : GradingFiles) {
        std::error_code error;
        if (fs::exists(folder + "/" + name, error))
            fs::rename(folder + "/" + name, kept + "/" + name);
    }
    return number + 1;
}

void writeGrading(const SubmissionOutcome& outcome, const std::string& submission,
                  const std::string& folder) {
    GradeReport report = outcome.report;
    report.earlierAttempts = earlierAttempts(folder);
    nlohmann::json labs = nlohmann::json::array();
    for (const LabMeasurement& m : outcome.measurements) labs.push_back(measurementJson(m, folder));
    writeFileAtomically(folder + "/measurements.json",
                        nlohmann::json{{"about", "what grading this submission measured, apart "
                                                 "from the rubric's points and thresholds: judged "
                                                 "again when only those change"},
                                       {"notes", outcome.report.notes},
                                       {"labs", labs}}
                                .dump(1) +
                            "\n");
    writeFileAtomically(folder + "/feedback.json", jsonReport(report));
    writeFileAtomically(folder + "/prairielearn.json", prairieLearnReport(report));
    writeHtmlReport(report, folder);
    writeFileAtomically(folder + "/result.json", resultJson(outcome, submission));
}

SubmissionOutcome gradeSubmission(const SubmissionGrader& grader, const std::string& submission,
                                  const std::string& folder, const std::string& scratchRoot,
                                  const std::string& id) {
    auto start = std::chrono::steady_clock::now();
    const auto began = start;
    SubmissionOutcome outcome;
    outcome.id = id.empty() ? submissionId(submission) : id;
    outcome.attempt = archiveAttempt(folder);
    const SandboxPolicy policy{grader.workCpus, sandboxUserForThisProcess()};
    const std::string sources = folder + "/submitted", build = folder + "/build",
                      scratch = scratchRoot + "/renders";
    for (const std::string& f : {sources, build, scratch}) {
        fs::remove_all(f);
        makeReadableFolder(f);
    }

    outcome.rubricHash = grader.rubric.hash;
    outcome.measurementHash = grader.rubric.measurementHash;
    outcome.speedMeasured = grader.measureSpeed;
    outcome.scenesHash = grader.scenesHash;
    outcome.intake = takeSubmission(submission, sources, policy);
    outcome.filesHash = labFilesHash(outcome.intake, sources);
    outcome.seconds.intake = secondsSince(start);
    GradeReport& report = outcome.report;
    // A problem quotes the submission's own names (an archive's members): its control bytes,
    // line ends included, are written as \xNN, so that it stays one line of the log.
    for (const std::string& problem : outcome.intake.problems)
        report.notes.push_back("submission: " + printableText(problem));
    if (outcome.intake.taken.empty()) {
        outcome.status = "no lab files found";
        for (Lab lab : AllLabs) {
            LabMeasurement none;
            none.lab = lab;
            none.ungraded = "not submitted";
            none.speedMeasured = grader.measureSpeed;
            outcome.measurements.push_back(none);
        }
    } else {
        start = std::chrono::steady_clock::now();
        const SubmissionLibrary library =
            buildSubmissionLibrary(grader.build, grader.kit, sources, build, policy);
        outcome.seconds.compile = secondsSince(start);
        GraderSetup setup = setupFor(grader, library, policy, scratch);
        if (grader.raceCheck.available())
            setup.raceCheck = raceCheckOf(grader, sources, build, policy, outcome.id);
        outcome.status = measureLabs(grader, library, setup, outcome);
    }
    for (const LabMeasurement& m : outcome.measurements)
        report.labs.push_back(judgeLab(grader.rubric, m));
    killProcessesOf(policy.user);
    fs::remove_all(scratch);
    report.seconds = secondsSince(began);
    writeGrading(outcome, submission, folder);
    return outcome;
}

std::string resultJson(const SubmissionOutcome& outcome, const std::string& submission) {
    nlohmann::json labs = nlohmann::json::object(), diagnoses = nlohmann::json::array();
    std::vector<std::string> missing;
    for (const LabGrade& lab : outcome.report.labs) {
        nlohmann::json checks = nlohmann::json::object();
        for (const CheckResult& c : lab.checks)
            checks[c.name()] = {{"score", c.score},
                                {"max_score", c.maxScore},
                                {"passed", c.passed},
                                {"graded_here", c.gradedHere}};
        labs[std::string(labName(lab.lab))] = {
            {"score", lab.score()}, {"max_score", lab.maxScore()}, {"checks", checks}};
        if (!outcome.intake.taken.count(labFileName(lab.lab)))
            missing.push_back(std::string(labName(lab.lab)));
        for (const CheckResult& c : lab.checks)
            if (!c.passed && !c.diagnosis.empty())
                diagnoses.push_back(
                    {{"lab", labName(lab.lab)}, {"check", c.name()}, {"diagnosis", c.diagnosis}});
    }
    nlohmann::json taken = nlohmann::json::object();
    for (const auto& [name, where] : outcome.intake.taken) taken[name] = where;
    const Intake& intake = outcome.intake;
    const nlohmann::json j = {{"id", outcome.id},
                              {"submission", submission},
                              {"status", outcome.status},
                              {"score", outcome.report.score()},
                              {"max_score", outcome.report.maxScore()},
                              {"labs", labs},
                              {"missing_labs", missing},
                              {"diagnoses", diagnoses},
                              {"seconds", outcome.report.seconds},
                              {"seconds_by_phase",
                               {{"intake", outcome.seconds.intake},
                                {"compile", outcome.seconds.compile},
                                {"correctness", outcome.seconds.labs.correctness},
                                {"race_check", outcome.seconds.labs.race},
                                {"speed", outcome.seconds.labs.speed}}},
                              {"attempt", outcome.attempt},
                              {"how", outcome.how},
                              {"graded_at", isoTime(static_cast<long long>(std::time(nullptr)))},
                              {"graded_under",
                               {{"rubric_hash", outcome.rubricHash},
                                {"measurement_hash", outcome.measurementHash},
                                {"speed_measured", outcome.speedMeasured},
                                {"scenes_hash", outcome.scenesHash},
                                {"kit_version", PATHLAB_VERSION}}},
                              {"intake",
                               {{"kind", intake.kind},
                                {"taken", taken},
                                {"problems", intake.problems},
                                {"commit", intake.commit},
                                {"files_hash", outcome.filesHash},
                                {"submitted_at", intake.submittedAt},
                                {"time_source", intake.timeSource},
                                {"lab_times", intake.labTimes}}}};
    return j.dump(1) + "\n";
}

} // namespace pathlab::grader
