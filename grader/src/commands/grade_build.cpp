// grader (no command): the labs of this build, run directly, as a student runs it before
// submitting; and make-references, which measures what they are compared with.
#include "checks/student_variant.h"
#include "checks/expectation.h"
#include "checks/grading_scenes.h"
#include "checks/kit_ray_cost.h"
#include "checks/rubric_text.h"
#include "checks/speed_check.h"
#include "commands/commands.h"
#include "commands/grade_lab.h"
#include "reports/lab_figures.h"
#include "reports/reports.h"
#include "reports/sweep_figures.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/progress_bar.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/whole_file.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <unistd.h>

namespace pathlab::grader {

namespace {

std::string labFiguresPath(const Arguments& a) { return a.references + "/lab_figures.json"; }

/// The kit's own cost of a ray on this machine, on the rubric's speed scene at the timed runs'
/// size (kit_ray_cost.h).
double kitCostOfARay(const Rubric& rubric, int threads) {
    return kitCpuSecondsPerRay(std::string(PATHLAB_MODELS_DIR) + "/" + rubric.speedScene + ".ecs",
                               rubric.width, rubric.height, threads);
}

/// The reference solutions' timed runs on this machine, with the kit's cost of a ray.
LabFigures timedLabFigures(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    GraderSetup setup;
    setup.solution = {a.solutionViewer, Implementation::Solution, {}, {}, {}};
    setup.rubric = rubric;
    setup.scratch = scratch;
    setup.threads = a.threads;
    // The timed runs render the speed scene as the correctness check does; no reference needed.
    GradingScene speed;
    speed.path = std::string(PATHLAB_MODELS_DIR) + "/" + rubric.speedScene + ".ecs";
    speed.reference.scene = rubric.speedScene;
    speed.name = rubric.speedScene;
    setup.scenes = {speed};
    LabFigures figures;
    figures.machine = thisMachine(a.threads);
    StartUpTimes startUps;
    {
        ProgressBar bar("lab figures: timed runs", "labs");
        int timed = 0;
        for (Lab lab : AllLabs) {
            const TimedFigures measured = timedFigures(setup, setup.solution, lab, startUps);
            figures.timedSamplesPerSecond[lab] = measured.samplesPerSecond;
            figures.timedRays[lab] = measured.rays;
            bar.update(++timed, static_cast<int>(AllLabs.size()));
        }
        figures.timedRaysKnown = true;
    }
    figures.kitCpuSecondsPerRay = kitCostOfARay(rubric, a.threads);
    return figures;
}

/// The reference solutions' notebook figures and timed runs on this machine.
void makeLabFigures(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    LabFigures figures = timedLabFigures(a, rubric, scratch);
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    std::fprintf(stderr, "lab figures: the notebook's renders ...\n");
    figures.notebook =
        measureNotebook(solution, notebookEstimators({AllLabs.begin(), AllLabs.end()}, rubric),
                        rubric, a.threads, scratch);
    for (const auto& [key, f] : figures.notebook)
        if (!f.failure.empty())
            throw std::runtime_error("the reference solution " + key + " failed: " + f.failure);
    saveLabFigures(labFiguresPath(a), figures, rubric);
    std::printf("wrote %s (%s)\n", labFiguresPath(a).c_str(), figures.machine.describe().c_str());
}

} // namespace

int makeReferences(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    std::filesystem::create_directories(a.references);
    if (a.onlyFigures) {
        makeLabFigures(a, rubric, scratch);
        return 0;
    }
    const LabRunner solution{a.solutionViewer, Implementation::Solution, {}, {}, {}};
    if (a.onlyHidden) {
        if (a.scenesDir.empty())
            throw InputError(
                "option --only-hidden: no hidden scenes (grader/hidden_scenes/ holds no .ecs; "
                "or name a folder with --scenes DIR)");
        std::vector<std::string> notes;
        gradingScenes(rubric, {a.references, a.scenesDir, a.referenceCache, a.revealHidden},
                      solution, scratch, notes);
        std::printf("the hidden scenes' references are in %s\n", a.referenceCache.c_str());
        return 0;
    }
    if (!a.onlyScene.empty() &&
        std::find(rubric.scenes.begin(), rubric.scenes.end(), a.onlyScene) == rubric.scenes.end())
        throw InputError("option --only-scene: '" + a.onlyScene +
                         "' is not a scene of the rubric's "
                         "correctness.scenes");
    for (const std::string& scene : rubric.scenes) {
        if (!a.onlyScene.empty() && scene != a.onlyScene) continue;
        if (a.onlyStale) {
            try {
                loadReference(a.references, publicScenePath(scene), rubric);
                std::printf("kept %s/%s.json: it fits the rubric\n", a.references.c_str(),
                            scene.c_str());
                continue;
            } catch (const InputError& why) {
                std::printf("measuring %s again: %s\n", scene.c_str(), why.what());
            }
        }
        ProgressBar bar(scene, "renders");
        const SceneReference ref = measureReference(
            solution, std::string(PATHLAB_MODELS_DIR) + "/" + scene + ".ecs", rubric, 40, 8,
            scratch, [&](int done, int total) { bar.update(done, total); });
        saveReference(a.references, ref);
        std::printf("wrote %s/%s.json\n", a.references.c_str(), scene.c_str());
    }
    if (a.onlyScene.empty() && !a.onlyStale) makeLabFigures(a, rubric, scratch);
    if (a.onlyStale) {
        // The figures are stale too when measured for other timed runs than the rubric's: a
        // release packed with a course rubric would otherwise have no speed estimate.
        // Only the timed runs where the notebook's figures (512x512 renders, minutes) still fit.
        const FiguresStaleness stale = labFiguresStaleness(labFiguresPath(a), rubric);
        if (!stale.notebook.empty()) {
            std::printf("measuring lab_figures.json again: %s\n", stale.notebook.c_str());
            makeLabFigures(a, rubric, scratch);
        } else if (!stale.timedRuns.empty()) {
            std::printf("measuring lab_figures.json's timed runs again: %s (its notebook "
                        "figures fit and are kept)\n",
                        stale.timedRuns.c_str());
            replaceTimedRuns(labFiguresPath(a), timedLabFigures(a, rubric, scratch), rubric);
        } else {
            std::printf("kept %s: it fits the rubric\n", labFiguresPath(a).c_str());
        }
    }
    return 0;
}

/// Where make convergence writes its plot: convergence/ beside make sweep's sweep/ (both in the
/// build folder).
std::string convergenceFolder(const std::string& sweeps) {
    return (std::filesystem::path(sweeps).parent_path() / "convergence").string();
}

void writeReports(const Arguments& a, const Rubric& rubric, const GradeReport& report) {
    if (!a.json.empty()) writeFileAtomically(a.json, jsonReport(report));
    if (!a.junit.empty()) writeFileAtomically(a.junit, junitReport(report));
    if (!a.gradescope.empty())
        writeFileAtomically(a.gradescope, gradescopeReport(report, rubric.hiddenScenesVisibility,
                                                           rubric.gradescopeLeaderboard));
    if (!a.prairielearn.empty()) writeFileAtomically(a.prairielearn, prairieLearnReport(report));
    if (!a.html.empty()) writeHtmlReport(report, a.html);
}

int gradeBuild(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    const auto start = std::chrono::steady_clock::now();
    std::fputs(releasedRubricNote(rubric, a.rubric).c_str(), stderr);
    GraderSetup setup;
    setup.student = {a.viewer, Implementation::Student, {}, {}, {}};
    setup.solution = {a.solutionViewer, Implementation::Solution, {}, {}, {}};
    setup.rubric = rubric;
    setup.scratch = scratch;
    setup.seedBase = a.seed;
    setup.threads = a.threads;
    setup.measureSpeed = a.speed && PATHLAB_HAS_SOLUTIONS;
    setup.solutionsAvailable = PATHLAB_HAS_SOLUTIONS;
    GradeReport report;
    std::optional<LabFigures> stored;
    try {
        stored = loadLabFigures(labFiguresPath(a), rubric);
    } catch (const InputError& e) {
        if (!setup.measureSpeed || !a.report.empty()) report.notes.push_back(e.what());
    }
    if (a.speed && !setup.measureSpeed) {
        report.notes.push_back("speed is not checked: this build has no reference solutions to "
                               "time your labs against (your instructor's grader does it)");
        setup.timeWithoutSolutions = true;
        if (stored) {
            setup.storedSolution = {stored->timedSamplesPerSecond, stored->timedRays,
                                    stored->timedRaysKnown, stored->kitCpuSecondsPerRay};
            report.ratiosReference = "the reference solutions on " + stored->machine.describe();
            if (stored->kitCpuSecondsPerRay > 0)
                setup.kitCpuSecondsPerRay = kitCostOfARay(rubric, a.threads);
        }
    }
    setup.scenes =
        gradingScenes(rubric, {a.references, a.scenesDir, a.referenceCache, a.revealHidden},
                      setup.solution, scratch, report.notes);
    if (!a.variant.empty()) {
        for (GradingScene& s : loadStudentVariantFolder(rubric, a.variant))
            setup.scenes.push_back(std::move(s));
    } else if (rubric.variants.perStudent) {
        report.notes.push_back(
            "your instructor grades each student on scenes of their own as well (the rubric's "
            "variants): `make grade VARIANT=DIR` grades you on yours, from the folder they send "
            "you");
    }
    report.ratiosMeasuredOn = "the correctness renders of " + rubric.speedScene + ", " +
                              std::to_string(rubric.width) + "×" + std::to_string(rubric.height) +
                              ", " + std::to_string(rubric.seeds) +
                              " seeds at each lab's samples per pixel; roulette as graded";
    StartUpTimes startUps;
    for (Lab lab : a.labs) {
        std::fprintf(stderr, "grading %s ...\n", std::string(labName(lab)).c_str());
        report.labs.push_back(gradeLab(setup, lab, startUps));
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fputs(terminalReport(report, ::isatty(STDOUT_FILENO)).c_str(), stdout);
    writeReports(a, rubric, report);
    if (!a.report.empty()) {
        std::fprintf(stderr, "measuring the lab notebook's figures ...\n");
        LabFigures yours;
        yours.machine = thisMachine(a.threads);
        yours.notebook = measureNotebook(setup.student, notebookEstimators(a.labs, rubric), rubric,
                                         a.threads, scratch);
        const std::string reportFolder = std::filesystem::absolute(a.report).parent_path().string();
        writeFileAtomically(
            a.report, labReport(report, rubric, yours, stored, observationsIn(a.report),
                                findSweeps(a.sweeps, reportFolder),
                                findConvergencePlot(convergenceFolder(a.sweeps), reportFolder)));
        std::printf("lab report: %s\n", a.report.c_str());
    }
    return report.score() == report.maxScore() ? 0 : 1;
}

} // namespace pathlab::grader
