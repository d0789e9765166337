// grader --report: the student's lab-notebook figures as a Markdown report to hand in, beside the
// reference solutions' stored ones, in the terms the handouts use.
#include "reports/reports.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace pathlab::grader {

namespace {

const std::string ObservationsHeading = "## What I observed";

std::string number(double value, const char* pattern = "%.3g") {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

/// One figure of one row, or why there is none.
std::string cell(const std::map<std::string, EstimatorFigures>& figures, const std::string& key,
                 double EstimatorFigures::*field, const char* pattern) {
    const auto found = figures.find(key);
    if (found == figures.end()) return "not measured";
    if (!found->second.failure.empty()) return "not measured: " + found->second.failure;
    return number(found->second.*field, pattern);
}

/// A row's figure over branching's, or why there is none.
std::string ratioCell(const std::map<std::string, EstimatorFigures>& figures,
                      const std::string& key, double EstimatorFigures::*field) {
    const auto row = figures.find(key), branching = figures.find("branching");
    if (row == figures.end() || branching == figures.end() || !row->second.failure.empty() ||
        !branching->second.failure.empty() || !(branching->second.*field > 0))
        return "not measured";
    // Three significant digits: lab 4's efficiency is a hundredth of lab 1's, which two decimals
    // would round to 0.01 whatever the lab.
    return number(row->second.*field / branching->second.*field, "%#.3g");
}

const LabGrade* gradeOf(const GradeReport& report, Lab lab) {
    for (const LabGrade& l : report.labs)
        if (l.lab == lab) return &l;
    return nullptr;
}

std::string verdict(const CheckResult& c) {
    if (c.atRisk) return "graded by the instructor: **at risk** (below)";
    if (!c.gradedHere) return "graded by the instructor";
    return std::string(c.passed ? "pass " : "**fail** ") + number(c.score, "%g") + "/" +
           number(c.maxScore, "%g");
}

/// The report's opening: where each side was measured, and what each figure means.
void writeIntroduction(std::ostream& md, const Rubric& rubric, const LabFigures& yours,
                       const std::optional<LabFigures>& reference) {
    const std::string size = std::to_string(NotebookSize), spp = std::to_string(NotebookSpp);
    md << "# PathLab lab report\n\n"
       << "Measured by `grader --report` on " << yours.machine.describe() << ".\n\n"
       << "The reference's figures are the reference solutions' "
       << (reference ? "on " + reference->machine.describe() +
                           ", stored in "
                           "`grader/references/lab_figures.json`"
                     : "(not stored in this kit: `grader make-references` measures them)")
       << ". Figures depend on the machine: compare the ratios between labs, yours with the "
          "reference's, not the absolute numbers. The ratios are taken of samples per CPU-second "
          "and of the efficiency per CPU-second, which other programs on the machine change "
          "little; the frame rate is wall-clock time, what you wait for, and a busy machine "
          "lowers it.\n\n"
       << "Each row is one headless render of `" << rubric.noiseScene << "`, " << size << "×"
       << size << " pixels, " << spp << " samples per pixel, maxDepth " << rubric.maxDepth
       << ", all cores, seed 0, as `./viewer -c models/" << rubric.noiseScene
       << ".ecs --lab LAB --spp " << spp
       << " -o LAB.png --stats LAB.json` renders it (add `--continue-prob "
       << number(rubric.continueProb, "%g") << "` for the graded roulette):\n\n"
       << "- *frame rate*: samples/s ÷ (" << size << " × " << size
       << "), the window's frame rate at " << size << "×" << size
       << " with one sample per pixel per frame (wall-clock time);\n"
       << "- *samples per CPU-second*: samples ÷ the CPU time the render threads spent "
          "rendering (`cpu_seconds` in --stats; the window's panel shows it too);\n"
       << "- *noise*: the relative standard error of the image after " << spp
       << " samples per pixel, the panel's noise figure (handouts/00-setup.md, \"The noise "
          "figure\");\n"
       << "- *efficiency*: 1/(noise² × CPU seconds); a noise of 0.01 takes 10⁴/efficiency "
          "CPU-seconds at this size (divide by the cores for the seconds you wait).\n\n";
}

/// Each estimator's figures, yours beside the reference's, with whether your lab is correct
/// (the figures of a wrong lab mean little).
void writeFiguresTable(std::ostream& md, const GradeReport& report,
                       const std::vector<NotebookEstimator>& rows,
                       const std::map<std::string, EstimatorFigures>& yours,
                       const std::map<std::string, EstimatorFigures>& theirs) {
    md << "## Your figures and the reference's\n\n"
       << "| estimator | your lab correct | frame rate: yours | reference | samples per "
          "CPU-second: yours | reference | noise at "
       << std::to_string(NotebookSpp)
       << " spp: yours | reference | efficiency: yours | reference |\n"
       << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const NotebookEstimator& row : rows) {
        const LabGrade* grade = gradeOf(report, row.lab);
        const bool correct = grade && !grade->checks.empty() && grade->checks[0].passed;
        md << "| " << row.label << " | " << (correct ? "yes" : "**no**") << " | "
           << cell(yours, row.key, &EstimatorFigures::framesPerSecond, "%.3g fps") << " | "
           << cell(theirs, row.key, &EstimatorFigures::framesPerSecond, "%.3g fps") << " | "
           << cell(yours, row.key, &EstimatorFigures::samplesPerCpuSecond, "%.3g") << " | "
           << cell(theirs, row.key, &EstimatorFigures::samplesPerCpuSecond, "%.3g") << " | "
           << cell(yours, row.key, &EstimatorFigures::noise, "%.3f") << " | "
           << cell(theirs, row.key, &EstimatorFigures::noise, "%.3f") << " | "
           << cell(yours, row.key, &EstimatorFigures::efficiency, "%.3g") << " | "
           << cell(theirs, row.key, &EstimatorFigures::efficiency, "%.3g") << " |\n";
    }
    // What --stats said of the student's renders: a busy machine, CPU time outside the render
    // threads. The figures stay; the words say how far to trust them.
    const auto sayNotes = [&](const std::map<std::string, EstimatorFigures>& figures,
                              const char* heading) {
        bool first = true;
        for (const NotebookEstimator& row : rows) {
            const auto found = figures.find(row.key);
            if (found == figures.end()) continue;
            for (const std::string& note : found->second.notes) {
                md << (first ? heading : "") << "- " << row.label << ": " << note << "\n";
                first = false;
            }
        }
    };
    sayNotes(yours, "\nNotes on your renders:\n\n");
    // The reference's figures were measured on the instructor's machine; its frame rates are
    // wall-clock time and fall as that machine was busy, which its notes say.
    sayNotes(theirs,
             "\nNotes on the reference's renders (grader/references/lab_figures.json):\n\n");
}

/// Each figure over lab 1's: the ratios carry over from one machine to another, where the
/// figures themselves do not.
void writeRatiosTable(std::ostream& md, const std::vector<NotebookEstimator>& rows,
                      const std::map<std::string, EstimatorFigures>& yours,
                      const std::map<std::string, EstimatorFigures>& theirs) {
    md << "\n## Ratios between the labs\n\nEach figure ÷ lab 1's (branching), of the renders "
          "above: these carry over from one machine to another, and from a quiet machine to a "
          "busy one, for they are measured in CPU time.\n\n"
       << "| estimator | samples per CPU-second ÷ lab 1's: yours | reference | noise ÷ lab 1's: "
          "yours | reference | efficiency ÷ lab 1's: yours | reference |\n"
       << "|---|--:|--:|--:|--:|--:|--:|\n";
    for (const NotebookEstimator& row : rows)
        md << "| " << row.label << " | "
           << ratioCell(yours, row.key, &EstimatorFigures::samplesPerCpuSecond) << " | "
           << ratioCell(theirs, row.key, &EstimatorFigures::samplesPerCpuSecond) << " | "
           << ratioCell(yours, row.key, &EstimatorFigures::noise) << " | "
           << ratioCell(theirs, row.key, &EstimatorFigures::noise) << " | "
           << ratioCell(yours, row.key, &EstimatorFigures::efficiency) << " | "
           << ratioCell(theirs, row.key, &EstimatorFigures::efficiency) << " |\n";
}

/// A row's noise after NotebookLateSpp, or why there is none.
std::string lateNoiseCell(const std::map<std::string, EstimatorFigures>& figures,
                          const std::string& key, bool stored) {
    const auto found = figures.find(key);
    if (found == figures.end() || !found->second.failure.empty()) return "not measured";
    if (!found->second.lateFailure.empty()) return "not measured: " + found->second.lateFailure;
    if (!(found->second.noiseLate > 0))
        return stored ? "not stored (grader make-references --only-figures)" : "not measured";
    return number(found->second.noiseLate, "%.3f");
}

/// The noise after NotebookLateSpp over the noise after NotebookSpp: 0.5 for an estimator of
/// finite variance (four times the samples, half the noise).
std::string lateRatioCell(const std::map<std::string, EstimatorFigures>& figures,
                          const std::string& key) {
    const auto found = figures.find(key);
    if (found == figures.end() || !(found->second.noiseLate > 0) || !(found->second.noise > 0))
        return "not measured";
    return number(found->second.noiseLate / found->second.noise, "%#.3g");
}

/// Lab 4's noise at 64 and at 256 spp, which handout 4 asks for: whether it halves.
void writeLateNoiseTable(std::ostream& md, const std::vector<NotebookEstimator>& rows,
                         const std::map<std::string, EstimatorFigures>& yours,
                         const std::map<std::string, EstimatorFigures>& theirs) {
    const std::string early = std::to_string(NotebookSpp), late = std::to_string(NotebookLateSpp);
    md << "\n## Lab 4: the noise at " << early << " and at " << late << " spp\n\n"
       << "Lab 4's rows rendered again at " << late << " samples per pixel (seed 0, as `--spp "
       << late
       << "` renders them): where the variance is finite the noise halves with four times "
          "the samples (a ratio of 0.5); where it is infinite it need not "
          "(handouts/04-russian-roulette.md, question 1).\n\n"
       << "| estimator | noise at " << early << " spp: yours | reference | noise at " << late
       << " spp: yours | reference | " << late << " ÷ " << early << ": yours | reference |\n"
       << "|---|--:|--:|--:|--:|--:|--:|\n";
    for (const NotebookEstimator& row : rows) {
        if (!measuresLateNoise(row)) continue;
        md << "| " << row.label << " | " << cell(yours, row.key, &EstimatorFigures::noise, "%.3f")
           << " | " << cell(theirs, row.key, &EstimatorFigures::noise, "%.3f") << " | "
           << lateNoiseCell(yours, row.key, false) << " | " << lateNoiseCell(theirs, row.key, true)
           << " | " << lateRatioCell(yours, row.key) << " | " << lateRatioCell(theirs, row.key)
           << " |\n";
    }
}

/// The student's own experiments (`make sweep`), or how to make them.
void writeExperiments(std::ostream& md, const std::vector<SweepFigure>& sweeps,
                      const std::string& convergencePlot) {
    md << "\n## My experiments\n\n";
    if (sweeps.empty()) {
        md << "No sweep run yet: `make sweep LAB=roulette` renders your lab 4 at continueProb "
              "0.05 to 0.95, `make sweep LAB=branching PARAM=max-depth` your lab 1 at maxDepth 1 "
              "to 8, and plots their samples per CPU-second, noise and efficiency beside the "
              "handout's "
              "figures; `make report` then shows the plots here.\n";
    } else {
        md << "Made by `make sweep` (scripts/sweep.py): your labs rendered at each value, beside "
              "the handout's figures of the reference solution.\n";
        for (const SweepFigure& sweep : sweeps) {
            md << "\n### " << sweep.lab << ": " << sweep.parameter << "\n\n"
               << "![" << sweep.lab << ": samples per CPU-second, noise and efficiency against "
               << sweep.parameter << "](" << sweep.plot << ")\n\n"
               << sweep.values << " values, numbers in [" << sweep.table << "](" << sweep.table
               << ")";
            if (!sweep.mostEfficient.empty())
                md << "; the most efficient: " << sweep.parameter << " " << sweep.mostEfficient;
            md << ".\n";
        }
    }
    if (convergencePlot.empty()) return;
    md << "\n### Error against render time\n\n"
       << "![the relative RMSE of my four labs against render time](" << convergencePlot
       << ")\n\nMade by `make convergence` (scripts/convergence.py): your four labs against the "
          "grader's references of the VI2 box, beside the handout's curves (dashed).\n";
}

/// The grader's verdicts, lab by lab, and how the noise check's statistic differs from the
/// noise figure above (students compare the two).
void writeChecksTable(std::ostream& md, const GradeReport& report, const Rubric& rubric) {
    md << "\n## The grader's checks\n\n"
       << "The noise check compares a different statistic from the noise figure above: the "
          "per-sample variance, measured from how "
       << rubric.seeds << " independent " << rubric.width << "×" << rubric.height
       << " renders differ pixel by pixel, the noisiest 1% "
          "of pixels left out, over the reference solution's (at most "
       << number(rubric.maxNoiseRatio, "%g") << ").\n\n"
       << "| lab | score | correctness | noise check: variance ÷ the reference's | speed check |\n"
       << "|---|---|---|---|---|\n";
    for (const LabGrade& lab : report.labs) {
        md << "| " << labName(lab.lab) << " | " << number(lab.score(), "%g") << "/"
           << number(lab.maxScore(), "%g");
        if (lab.pointsNotGradedHere() > 0)
            md << " (+" << number(lab.pointsNotGradedHere(), "%g")
               << " speed: graded by the instructor"
               << (lab.pointsAtRisk() > 0 ? "; **at risk**" : "") << ")";
        md << " |";
        for (const CheckResult& c : lab.checks) {
            md << " " << verdict(c);
            if (c.kind == CheckKind::Noise && lab.solutionVariance > 0)
                md << ": " << number(lab.studentVariance / lab.solutionVariance, "%.2f");
            if (c.kind == CheckKind::Speed && lab.studentSamplesPerSecond > 0)
                md << (c.gradedHere ? ": " : "; yours here ") << number(lab.studentSamplesPerSecond)
                   << " samples per CPU-second";
            md << " |";
        }
        if (lab.checks.size() < 3) md << " not measured (--no-speed) |";
        md << "\n";
    }
    for (const LabGrade& lab : report.labs)
        for (const CheckResult& c : lab.checks)
            if (c.atRisk) {
                md << "\n**" << labName(lab.lab) << ", speed:** " << c.summary << "\n";
                for (const std::string& d : c.details) md << "- " << d << "\n";
            }
}

/// The student's own section: what they wrote there before, kept, or the prompt.
void writeObservations(std::ostream& md, const std::string& observations) {
    md << "\n" << ObservationsHeading << "\n\n";
    if (observations.empty())
        md << "<!-- For each lab: what the frame rate and the noise tell you about the estimator, "
              "and your answers to the handout's questions. What you write below this heading "
              "is kept when make report writes this file again. -->\n";
    else
        md << observations;
}

} // namespace

std::string labReport(const GradeReport& report, const Rubric& rubric, const LabFigures& yours,
                      const std::optional<LabFigures>& reference, const std::string& observations,
                      const std::vector<SweepFigure>& sweeps, const std::string& convergencePlot) {
    std::vector<Lab> labs;
    for (const LabGrade& l : report.labs) labs.push_back(l.lab);
    const std::vector<NotebookEstimator> rows = notebookEstimators(labs, rubric);
    static const std::map<std::string, EstimatorFigures> none;
    const auto& theirs = reference ? reference->notebook : none;
    std::ostringstream md;
    writeIntroduction(md, rubric, yours, reference);
    writeFiguresTable(md, report, rows, yours.notebook, theirs);
    if (yours.notebook.count("branching")) writeRatiosTable(md, rows, yours.notebook, theirs);
    if (std::any_of(rows.begin(), rows.end(), measuresLateNoise))
        writeLateNoiseTable(md, rows, yours.notebook, theirs);
    writeExperiments(md, sweeps, convergencePlot);
    writeChecksTable(md, report, rubric);
    writeObservations(md, observations);
    return md.str();
}

std::string observationsIn(const std::string& path) {
    std::ifstream in(path);
    std::string line, kept;
    bool below = false;
    while (std::getline(in, line)) {
        if (below)
            kept += line + "\n";
        else
            below = line == ObservationsHeading;
    }
    const size_t first = kept.find_first_not_of(" \n");
    if (first == std::string::npos) return "";
    kept = kept.substr(first);
    // The prompt alone, as make report wrote it: nothing of the student's to keep.
    const size_t promptEnd = kept.find("-->");
    const bool promptOnly = kept.rfind("<!--", 0) == 0 && promptEnd != std::string::npos &&
                            kept.find_first_not_of(" \n", promptEnd + 3) == std::string::npos;
    return promptOnly ? "" : kept;
}

} // namespace pathlab::grader
