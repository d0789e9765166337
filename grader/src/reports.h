#pragma once
/// The grader's verdict in the formats people and platforms read.

#include "grading.h"

#include <string>
#include <vector>

namespace pathlab::grader {

struct GradeReport {
    std::vector<LabGrade> labs;
    double seconds = 0;
    std::vector<std::string> notes; ///< e.g. references measured on the fly

    double score() const;
    double maxScore() const;
};

/// `text` with & < > " escaped, for XML and HTML.
std::string escapeXml(const std::string& text);

/// A table for the terminal, coloured when `colour`.
std::string terminalReport(const GradeReport& report, bool colour);
std::string jsonReport(const GradeReport& report);
std::string junitReport(const GradeReport& report);
/// Gradescope's results.json: score, execution_time, output, tests[] (name, score, max_score,
/// status, output, visibility).
std::string gradescopeReport(const GradeReport& report);
/// A Markdown lab report for a student to hand in: per lab, samples/s, frame rate and noise,
/// theirs beside the reference's, and the speed ratios between labs.
std::string labReport(const GradeReport& report, int speedWidth, int speedHeight,
                      const std::string& noiseScene);
/// Writes DIR/index.html, one self-contained page (images embedded).
void writeHtmlReport(const GradeReport& report, const std::string& folder);

/// The speed ratios between labs the handouts ask for (uniform/branching, ...), from the
/// labs graded: {name, student ratio, reference ratio}.
struct LabRatio {
    std::string name;
    double student, reference;
};
std::vector<LabRatio> labRatios(const GradeReport& report);

} // namespace pathlab::grader
