// grader (no command): the labs of this build, run directly, as a student runs it before
// submitting; and make-references, which measures what they are compared with.
#include "commands.h"
#include "expectation.h"
#include "grading_scenes.h"
#include "progress_bar.h"
#include "reports.h"

#include "pathlab/render_stats.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace pathlab::grader {

int makeReferences(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    std::filesystem::create_directories(a.references);
    const LabRunner solution{a.solutionViewer, Implementation::Solution, "", {}, {}};
    for (const std::string& scene : rubric.scenes) {
        ProgressBar bar(scene, "renders");
        const SceneReference ref = measureReference(
            solution, std::string(PATHLAB_MODELS_DIR) + "/" + scene + ".ecs", rubric, 40, 8,
            scratch, [&](int done, int total) { bar.update(done, total); });
        saveReference(a.references, ref);
        std::printf("wrote %s/%s.json\n", a.references.c_str(), scene.c_str());
    }
    return 0;
}

void writeReports(const Arguments& a, const GradeReport& report) {
    if (!a.json.empty()) writeFileAtomically(a.json, jsonReport(report));
    if (!a.junit.empty()) writeFileAtomically(a.junit, junitReport(report));
    if (!a.gradescope.empty()) writeFileAtomically(a.gradescope, gradescopeReport(report));
    if (!a.html.empty()) writeHtmlReport(report, a.html);
}

int gradeBuild(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    const auto start = std::chrono::steady_clock::now();
    GraderSetup setup;
    setup.student = {a.viewer, Implementation::Student, "", {}, {}};
    setup.solution = {a.solutionViewer, Implementation::Solution, "", {}, {}};
    setup.rubric = rubric;
    setup.scratch = scratch;
    setup.seedBase = a.seed;
    setup.threads = a.threads;
    setup.measureSpeed = a.speed && PATHLAB_HAS_SOLUTIONS;
    GradeReport report;
    if (a.speed && !setup.measureSpeed)
        report.notes.push_back("speed is not checked: this build has no reference solutions to "
                               "time your labs against (your instructor's grader does it)");
    setup.scenes = gradingScenes(rubric, a.references, a.scenesDir, "", setup.solution, scratch, report.notes);
    for (Lab lab : a.labs) {
        std::fprintf(stderr, "grading %s ...\n", std::string(labName(lab)).c_str());
        report.labs.push_back(gradeLab(setup, lab));
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fputs(terminalReport(report, ::isatty(STDOUT_FILENO)).c_str(), stdout);
    writeReports(a, report);
    if (!a.report.empty()) {
        writeFileAtomically(a.report, labReport(report, rubric.speedWidth, rubric.speedHeight, rubric.noiseScene));
        std::printf("lab report: %s\n", a.report.c_str());
    }
    return report.score() == report.maxScore() ? 0 : 1;
}

} // namespace pathlab::grader
