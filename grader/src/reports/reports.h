#pragma once
/// The grader's verdict in the formats people and platforms read.

#include "checks/check_result.h"
#include "reports/lab_figures.h"
#include "reports/sweep_figures.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

struct GradeReport {
    std::vector<LabGrade> labs;
    double seconds = 0;
    std::vector<std::string> notes; ///< e.g. references measured on the fly
    /// Where the reference's side of the speed ratios comes from, when not from timing the
    /// solutions beside the student's labs now: "the reference solutions on <machine>".
    std::string ratiosReference;
    /// What the speed ratios between labs were measured on, in words (the timed runs' scene,
    /// size and samples); empty: not said.
    std::string ratiosMeasuredOn;
    /// A submission's earlier gradings (a batch keeps each in attempts/N/), oldest first.
    struct Attempt {
        int number = 0;
        double score = 0, maxScore = 0;
        std::string gradedAt; ///< UTC, ISO 8601
        std::string how;      ///< "graded", or "re-scored" from an earlier attempt's measurements
    };
    std::vector<Attempt> earlierAttempts;
    /// The fraction of the score a late submission loses (the rubric's late policy, applied by
    /// `grader submission --submitted-at`): Gradescope's and PrairieLearn's scores are after it.
    double latePenalty = 0;

    double score() const;
    double maxScore() const; ///< of the checks graded here
    double pointsNotGradedHere() const;
    double pointsAtRisk() const; ///< of those not graded here, the ones this build warns of
};

/// `text` with & < > " escaped, for XML and HTML.
std::string escapeXml(const std::string& text);

/// `text` as a CSV field: quoted, its quotes doubled, where it holds a comma, quote or newline.
std::string csvField(const std::string& text);

/// Where a report puts the hidden scenes' verdicts.
enum class HiddenVerdicts {
    Shown,          ///< under their check (the terminal, the student's feedback)
    InTheirOwnTest, ///< a pointer to the test "LAB: hidden scenes" (Gradescope)
    LeftOut,        ///< nowhere (PrairieLearn, which cannot show a test only after the due date)
};

/// A table for the terminal, coloured when `colour`, the hidden scenes' verdicts as `hidden` says.
std::string terminalReport(const GradeReport& report, bool colour,
                           HiddenVerdicts hidden = HiddenVerdicts::Shown);
std::string jsonReport(const GradeReport& report);
std::string junitReport(const GradeReport& report);
/// Gradescope's results.json: score, execution_time, output, tests[] (name, score, max_score,
/// status, output, visibility). Each lab graded on hidden scenes has a test "LAB: hidden scenes"
/// (no points of its own) with `hiddenVisibility` (rubric: hidden_scenes.gradescope_visibility).
std::string gradescopeReport(const GradeReport& report, const std::string& hiddenVisibility,
                             bool leaderboard = false);
/// PrairieLearn's external-grader results.json: gradable, score (a fraction of the maximum),
/// message, output, tests[] (name, description, points, max_points, message, output), a test per
/// lab and check graded here. The hidden scenes' verdicts are left out: PrairieLearn has no
/// setting that shows a test only after the due date.
std::string prairieLearnReport(const GradeReport& report);
/// A Markdown lab report for a student to hand in: the notebook's figures (frame rate, noise,
/// efficiency) of each lab beside the reference solutions' stored ones, the ratios between labs,
/// lab 4's noise at 64 and 256 spp, the student's `make sweep` plots (`sweeps`, or how to make
/// them) and `make convergence` plot (`convergencePlot`, when there is one), and the grader's
/// verdicts; then the student's own section, "What I observed":
/// `observations` as it stands in the report being replaced (observationsIn), or a prompt when
/// there is none.
std::string labReport(const GradeReport& report, const Rubric& rubric, const LabFigures& yours,
                      const std::optional<LabFigures>& reference, const std::string& observations,
                      const std::vector<SweepFigure>& sweeps = {},
                      const std::string& convergencePlot = "");
/// What a student wrote under "## What I observed" in the report at `path` ("" if none): kept when
/// `make report` writes the report again.
std::string observationsIn(const std::string& path);
/// Writes DIR/index.html, one self-contained page (images embedded).
void writeHtmlReport(const GradeReport& report, const std::string& folder);

/// The speed ratios between labs the notebook asks for (each lab's samples/s ÷ branching's), from
/// the grader's timed runs of the labs graded: {name, student ratio, reference ratio (0 when
/// unknown)}.
struct LabRatio {
    std::string name;
    double student, reference;
};
std::vector<LabRatio> labRatios(const GradeReport& report);

} // namespace pathlab::grader
