#include "checks/pick_report.h"

#include "checks/grading_scenes.h"
#include "checks/run_limits.h"
#include "isolation/render_run.h"

#include "pathlab/support/printable_text.h"

#include <sstream>

namespace pathlab::grader {

namespace {

/// A quoted line is cut here: the lab's process wrote it.
constexpr size_t LongestLine = 300;

} // namespace

std::vector<std::string> pickTestFailures(const std::string& output, size_t most) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    std::string line;
    bool failed = false;
    while (std::getline(in, line) && lines.size() < most) {
        if (line == "FAILED:") {
            failed = true;
        } else if (failed && line.rfind("  at ", 0) == 0) {
            line = printableText(line.substr(2));
            if (line.size() > LongestLine) line = line.substr(0, LongestLine) + "...";
            lines.push_back(line);
        } else {
            failed = false;
        }
    }
    return lines;
}

void addPickTestReport(const GraderSetup& setup, Lab lab, CheckResult& correctness) {
    const Rubric& r = setup.rubric;
    LabToolRequest request;
    request.runner = &setup.student;
    request.lab = lab;
    request.scene = publicScenePath(PickTestScene);
    request.scratch = setup.scratch;
    request.arguments = {"--size",
                         "64",
                         "64",
                         "--max-depth",
                         std::to_string(r.maxDepth),
                         "--continue-prob",
                         std::to_string(r.continueProb),
                         "--pick-test"};
    // 1 is its verdict that the picks differ, not a failure of the run.
    request.succeeded = [](const ProcessOutcome& p) {
        return p.signal == 0 && !p.timedOut && (p.exitStatus == 0 || p.exitStatus == 1);
    };
    const LabToolRun run = runLabTool(request, limitsOf(setup));
    if (!run.ok) return;
    for (const std::string& line : pickTestFailures(run.output))
        correctness.details.push_back("the pick test (`make pick-test`, 16 samples of 32x32 "
                                      "pixels of " +
                                      std::string(PickTestScene) + "): " + line);
}

} // namespace pathlab::grader
