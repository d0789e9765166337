// grader submission: one submitted set of labs graded in the sandbox, its feedback written; the
// command each job of `grader batch` runs (batch.cpp), and an instructor may run by hand.
#include "checks/grading_scenes.h"
#include "checks/student_variant.h"
#include "commands/commands.h"
#include "commands/grading_host.h"
#include "commands/output_lock.h"
#include "commands/submission_grading.h"
#include "common/plain_id.h"
#include "reports/submission_time.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/support/input_error.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace pathlab::grader {

namespace {

/// The rubric's late policy on a submission handed in at --submitted-at against --deadline (as
/// Gradescope's submission_metadata.json gives them): the fraction it loses goes into the
/// report, which Gradescope's and PrairieLearn's scores are after, and a note says why.
void applyLatePolicy(const Arguments& a, const Rubric& rubric, SubmissionOutcome& outcome) {
    const auto submitted = parseTime(a.submittedAt), deadline = parseTime(a.deadline);
    if (!submitted)
        throw InputError("option --submitted-at: '" + a.submittedAt + "' is not a time");
    if (!deadline) throw InputError("option --deadline: '" + a.deadline + "' is not a time");
    if (!rubric.late.given) {
        if (*submitted > *deadline)
            outcome.report.notes.push_back("handed in after the deadline; the rubric has no late "
                                           "policy, so the score is not lowered");
        return;
    }
    char note[400];
    if (rubric.late.perLab()) {
        // Each lab handed in now, against its own deadline (--deadline for a lab without one).
        std::map<std::string, long long> times;
        std::map<std::string, double> scores;
        for (const LabGrade& lab : outcome.report.labs) {
            scores[std::string(labName(lab.lab))] = lab.score();
            if (outcome.intake.taken.count(labFileName(lab.lab)))
                times[std::string(labName(lab.lab))] = *submitted;
        }
        const std::vector<LabLateness> labs =
            labLatenessOf(rubric.late, outcome.id, times, *deadline);
        const std::string late = lateLabsText(labs);
        if (late.empty()) return;
        outcome.report.latePenalty = totalPenalty(labs, scores);
        std::snprintf(note, sizeof note,
                      "late: %s: the score loses %g%% (the rubric's late policy, a deadline per "
                      "lab), %g of %g",
                      late.c_str(), std::round(1000 * outcome.report.latePenalty) / 10,
                      outcome.report.score() * (1 - outcome.report.latePenalty),
                      outcome.report.maxScore());
        outcome.report.notes.push_back(note);
        return;
    }
    const Lateness late = latenessOf(rubric.late, outcome.id, *submitted, *deadline);
    if (late.daysLate == 0) return;
    outcome.report.latePenalty = late.penalty;
    std::snprintf(note, sizeof note,
                  "late: %d day(s) after the deadline, %d slip day(s) forgiven: the score loses "
                  "%g%% (the rubric's late policy), %g of %g",
                  late.daysLate, late.slipDaysUsed, late.penalty * 100,
                  outcome.report.score() * (1 - late.penalty), outcome.report.maxScore());
    outcome.report.notes.push_back(note);
}

} // namespace

int gradeOneSubmission(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    requireSandbox();
    const OutputLock lock(a.out, "grading of a submission");
    // The student: --id where the submission's folder does not name them (PrairieLearn's is
    // always /grade/student), as the grader spells ids.
    const std::string id = a.id.empty() ? submissionId(a.inputs[0]) : plainId(a.id);
    SubmissionGrader g;
    g.build = labBuildOfThisGrader();
    g.rubric = rubric;
    g.workCpus = a.workCpus;
    // The kit holds the compiled reference solutions: in the scratch folder, which goes with
    // this run, never in OUT, which an instructor may hand back to the student whole.
    g.kit = a.kit.empty()
                ? buildLabKit(g.build, scratch + "/kit", {a.workCpus, sandboxUserForThisProcess()})
                : existingLabKit(a.kit);
    // References of hidden scenes come from the solutions, linked into this build's viewer.
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    std::vector<std::string> notes;
    g.scenes = gradingScenes(rubric, {a.references, a.scenesDir, a.referenceCache, a.revealHidden},
                             solution, scratch, notes);
    if (rubric.variants.perStudent) {
        // The student's own scenes, written beside their feedback: theirs to look at.
        const StudentVariant variant =
            drawStudentVariant(rubric.variants, classSecret(rubric.variants), id);
        for (GradingScene& s : studentVariantScenes(rubric, variant, a.out + "/variant", solution,
                                                    scratch, a.referenceCache))
            g.scenes.push_back(std::move(s));
    }
    g.scenesHash = scenesHash(rubric, a.scenesDir);
    g.timing = {a.timingCpus, a.timingLock, a.timingCpus.empty() ? 0 : 1};
    g.threads = a.workCpus.empty() ? a.threads : static_cast<int>(a.workCpus.size());
    g.seedBase = a.seed;
    g.measureSpeed = a.speed;
    if (a.raceCheck) {
        g.raceCheck = raceCheckRuntime(g.build, {a.workCpus, sandboxUserForThisProcess()});
        if (!g.raceCheck.available())
            std::fprintf(stderr, "race check skipped: %s\n", g.raceCheck.unavailable.c_str());
    }
    SubmissionOutcome outcome = gradeSubmission(g, a.inputs[0], a.out, scratch, id);
    outcome.report.notes.insert(outcome.report.notes.begin(), notes.begin(), notes.end());
    if (!a.submittedAt.empty()) applyLatePolicy(a, rubric, outcome);
    std::printf("%s: %s\n", outcome.id.c_str(), outcome.status.c_str());
    std::fputs(terminalReport(outcome.report, false).c_str(), stdout);
    writeReports(a, rubric, outcome.report);
    // As every command that grades: 1 when a check failed (or a lab was not graded).
    return outcome.report.score() == outcome.report.maxScore() ? 0 : 1;
}

} // namespace pathlab::grader
