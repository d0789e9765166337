#include "submission_grading.h"

#include "pathlab/render_stats.h"

#include <nlohmann/json.hpp>

#include <chrono>
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

} // namespace

SubmissionOutcome gradeSubmission(const SubmissionGrader& grader, const std::string& submission,
                                  const std::string& folder) {
    const auto start = std::chrono::steady_clock::now();
    SubmissionOutcome outcome;
    outcome.id = submissionId(submission);
    const SandboxPolicy policy{grader.workCpus, sandboxUserForThisProcess()};
    const std::string sources = folder + "/submitted", build = folder + "/build",
                      scratch = folder + "/scratch";
    for (const std::string& f : {sources, build, scratch}) {
        fs::remove_all(f);
        makeReadableFolder(f);
    }

    outcome.intake = takeSubmission(submission, sources, policy);
    GradeReport& report = outcome.report;
    for (const std::string& problem : outcome.intake.problems) report.notes.push_back("submission: " + problem);
    if (outcome.intake.taken.empty()) {
        outcome.status = "no lab files found";
        for (Lab lab : AllLabs)
            report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed, "not submitted", {}));
    } else {
        const SubmissionLibrary library = buildSubmissionLibrary(grader.build, grader.kit, sources, build, policy);
        GraderSetup setup;
        setup.student = {grader.build.viewer, Implementation::Student, library.library, policy, {}};
        const std::string& solutions = grader.kit.solutionsLibrary;
        setup.solution = {grader.build.viewer, Implementation::Student,
                          {solutions, solutions, solutions, solutions}, policy, {}};
        setup.timing = grader.timing;
        setup.rubric = grader.rubric;
        setup.scenes = grader.scenes;
        setup.scratch = scratch;
        setup.seedBase = grader.seedBase;
        setup.threads = grader.threads;
        setup.measureSpeed = grader.measureSpeed;
        setup.runSeconds = grader.runSeconds;
        std::string broken, unlinked; // names of the labs that do not compile, do not link
        for (Lab lab : AllLabs) {
            const int i = static_cast<int>(lab);
            const LabCompilation& compiled = library.labs[i];
            if (compiled.status == LabCompilation::Status::NotSubmitted) {
                report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed, "not submitted", {}));
            } else if (compiled.status == LabCompilation::Status::Failed) {
                broken += (broken.empty() ? "" : " ") + std::string(labName(lab));
                report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed,
                                                  "does not compile", {compiled.messages}));
            } else if (!library.linked(lab)) {
                unlinked += (unlinked.empty() ? "" : " ") + std::string(labName(lab));
                report.labs.push_back(ungradedLab(grader.rubric, lab, grader.measureSpeed,
                                                  "does not link", {library.problem[i]}));
            } else {
                report.labs.push_back(gradeLab(setup, lab));
            }
        }
        outcome.status = "graded";
        if (!broken.empty()) outcome.status += "; does not compile: " + broken;
        if (!unlinked.empty()) outcome.status += "; does not link: " + unlinked;
    }
    killProcessesOf(policy.user);
    fs::remove_all(scratch);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    writeFileAtomically(folder + "/feedback.json", jsonReport(report));
    writeHtmlReport(report, folder);
    writeFileAtomically(folder + "/result.json", resultJson(outcome, submission));
    return outcome;
}

std::string resultJson(const SubmissionOutcome& outcome, const std::string& submission) {
    nlohmann::json labs = nlohmann::json::object(), diagnoses = nlohmann::json::array();
    for (const LabGrade& lab : outcome.report.labs) {
        labs[std::string(labName(lab.lab))] = {{"score", lab.score()}, {"max_score", lab.maxScore()}};
        for (const CheckResult& c : lab.checks)
            if (!c.passed && !c.diagnosis.empty())
                diagnoses.push_back({{"lab", labName(lab.lab)}, {"check", c.name}, {"diagnosis", c.diagnosis}});
    }
    nlohmann::json taken = nlohmann::json::object();
    for (const auto& [name, where] : outcome.intake.taken) taken[name] = where;
    const nlohmann::json j = {{"id", outcome.id},
                              {"submission", submission},
                              {"status", outcome.status},
                              {"score", outcome.report.score()},
                              {"max_score", outcome.report.maxScore()},
                              {"labs", labs},
                              {"diagnoses", diagnoses},
                              {"seconds", outcome.report.seconds},
                              {"intake", {{"kind", outcome.intake.kind}, {"taken", taken},
                                          {"problems", outcome.intake.problems}}}};
    return j.dump(1) + "\n";
}

} // namespace pathlab::grader
