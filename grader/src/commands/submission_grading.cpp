#include "commands/submission_grading.h"

#include "commands/grade_lab.h"
#include "common/content_hash.h"

#include "pathlab/render_stats.h"
#include "pathlab/whole_file.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>

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
    RaceCheckRun races;
    races.build = grader.build;
    races.kit = grader.kit;
    races.runtime = grader.raceCheck;
    races.sources = sources;
    races.folder = build;
    races.policy = policy;
    races.timingCpus = grader.timing.cpus;
    races.timingLock = grader.timing.lockFile;
    races.seed = grader.seedBase;
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

/// Grades each lab that compiled and linked, and reports the others ungraded with the reason;
/// returns the submission's status: graded, and which labs were not submitted, do not compile
/// or do not link.
std::string gradeLabs(const SubmissionGrader& grader, const SubmissionLibrary& library,
                      const GraderSetup& setup, GradeReport& report) {
    StartUpTimes startUps;        // this submission's: its labs' libraries are its own
    std::string broken, unlinked; // names of the labs that do not compile, do not link
    for (Lab lab : AllLabs) {
        const LabCompilation& compiled = library.labs[lab];
        if (compiled.status == LabCompilation::Status::NotSubmitted) {
            report.labs.push_back(
                ungradedLab(grader.rubric, lab, grader.measureSpeed, "not submitted", {}));
        } else if (compiled.status == LabCompilation::Status::Failed) {
            addLabName(broken, lab);
            report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed,
                                              "does not compile", {compiled.messages}));
        } else if (!library.linked(lab)) {
            addLabName(unlinked, lab);
            report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed,
                                              "does not link", {library.problem[lab]}));
        } else {
            report.labs.push_back(gradeLab(setup, lab, startUps));
        }
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

} // namespace

SubmissionOutcome gradeSubmission(const SubmissionGrader& grader, const std::string& submission,
                                  const std::string& folder, const std::string& scratchRoot) {
    const auto start = std::chrono::steady_clock::now();
    SubmissionOutcome outcome;
    outcome.id = submissionId(submission);
    const SandboxPolicy policy{grader.workCpus, sandboxUserForThisProcess()};
    const std::string sources = folder + "/submitted", build = folder + "/build",
                      scratch = scratchRoot + "/renders";
    for (const std::string& f : {sources, build, scratch}) {
        fs::remove_all(f);
        makeReadableFolder(f);
    }

    outcome.rubricHash = grader.rubric.hash;
    outcome.scenesHash = grader.scenesHash;
    outcome.intake = takeSubmission(submission, sources, policy);
    ContentHash files;
    for (const auto& [name, where] : outcome.intake.taken)
        files.add(name).addFile(sources + "/" + name);
    outcome.filesHash = files.hex();
    GradeReport& report = outcome.report;
    for (const std::string& problem : outcome.intake.problems)
        report.notes.push_back("submission: " + problem);
    if (outcome.intake.taken.empty()) {
        outcome.status = "no lab files found";
        for (Lab lab : AllLabs)
            report.labs.push_back(
                ungradedLab(grader.rubric, lab, grader.measureSpeed, "not submitted", {}));
    } else {
        const SubmissionLibrary library =
            buildSubmissionLibrary(grader.build, grader.kit, sources, build, policy);
        GraderSetup setup = setupFor(grader, library, policy, scratch);
        if (grader.raceCheck.available())
            setup.raceCheck = raceCheckOf(grader, sources, build, policy, outcome.id);
        outcome.status = gradeLabs(grader, library, setup, report);
    }
    killProcessesOf(policy.user);
    fs::remove_all(scratch);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    writeFileAtomically(folder + "/feedback.json", jsonReport(report));
    writeHtmlReport(report, folder);
    writeFileAtomically(folder + "/result.json", resultJson(outcome, submission));
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
        if (!outcome.intake.taken.count(std::string(labName(lab.lab)) + ".cpp"))
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
                              {"graded_under",
                               {{"rubric_hash", outcome.rubricHash},
                                {"scenes_hash", outcome.scenesHash},
                                {"kit_version", PATHLAB_VERSION}}},
                              {"intake",
                               {{"kind", intake.kind},
                                {"taken", taken},
                                {"problems", intake.problems},
                                {"commit", intake.commit},
                                {"files_hash", outcome.filesHash},
                                {"submitted_at", intake.submittedAt},
                                {"time_source", intake.timeSource}}}};
    return j.dump(1) + "\n";
}

} // namespace pathlab::grader
