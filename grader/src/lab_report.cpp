// grader --report: the student's measurements as a Markdown report to hand in, beside the
// reference's, in the terms the handouts use.
#include "reports.h"

#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace pathlab::grader {

namespace {

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "an unknown processor";
}

std::string figure(double value, const char* pattern = "%.3g") {
    if (!(value > 0)) return "–";
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

std::string labReport(const GradeReport& report, int speedWidth, int speedHeight,
                      const std::string& noiseScene) {
    char date[32];
    const std::time_t now = std::time(nullptr);
    std::strftime(date, sizeof date, "%Y-%m-%d", std::localtime(&now));
    // The viewer's frame rate at 512×512 and one sample per pixel per frame.
    const double pixels = 512.0 * 512.0;
    std::ostringstream md;
    md << "# PathLab lab report\n\n"
       << "Measured by `grader --report` on " << date << ", on " << cpuModel() << " ("
       << std::thread::hardware_concurrency() << " cores), PathLab " << PATHLAB_VERSION << ".\n\n"
       << "- *samples/s*: the median of the grader's timed renders (" << speedWidth << "×"
       << speedHeight << "), yours and the reference's interleaved.\n"
       << "- *frame rate*: samples/s ÷ (512 × 512), the viewer's frame rate at 512×512 with one "
          "sample per pixel per frame.\n"
       << "- *noise*: the variance of one sample (one path) on " << noiseScene
       << ", averaged over pixels; a pixel's error after n samples is √(variance / n).\n\n"
       << "| lab | correct | samples/s (yours) | samples/s (reference) | speed ratio | frame rate "
          "(yours) | frame rate (reference) | noise (yours) | noise (reference) | noise ratio |\n"
       << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const LabGrade& lab : report.labs) {
        const bool correct = !lab.checks.empty() && lab.checks[0].passed;
        const double speed = lab.solutionSamplesPerSecond > 0
                                 ? lab.studentSamplesPerSecond / lab.solutionSamplesPerSecond : 0;
        const double noise = lab.solutionVariance > 0 ? lab.studentVariance / lab.solutionVariance : 0;
        md << "| " << labName(lab.lab) << " | " << (correct ? "yes" : "**no**") << " | "
           << figure(lab.studentSamplesPerSecond) << " | " << figure(lab.solutionSamplesPerSecond)
           << " | " << figure(speed, "%.2f") << " | "
           << figure(lab.studentSamplesPerSecond / pixels, "%.1f fps") << " | "
           << figure(lab.solutionSamplesPerSecond / pixels, "%.1f fps") << " | "
           << figure(lab.studentVariance) << " | " << figure(lab.solutionVariance) << " | "
           << figure(noise, "%.2f") << " |\n";
    }
    const auto ratios = labRatios(report);
    if (!ratios.empty()) {
        md << "\n## Speed ratios between the labs\n\n| ratio | yours | reference |\n|---|---|---|\n";
        for (const LabRatio& r : ratios)
            md << "| " << r.name << " | " << figure(r.student, "%.2f") << " | "
               << figure(r.reference, "%.2f") << " |\n";
    }
    md << "\n## What I observed\n\n"
          "<!-- For each lab: what the frame rate and the noise tell you about the estimator, "
          "and your answers to the handout's questions. -->\n";
    return md.str();
}

} // namespace pathlab::grader
