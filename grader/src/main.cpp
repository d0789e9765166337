// grader: grades the labs of a build (or of a submission's viewer) for correctness, noise and
// speed against the reference solutions, and writes its verdict for people and platforms.
#include "expectation.h"
#include "grading.h"
#include "reports.h"

#include "pathlab/input_error.h"
#include "pathlab/render_stats.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace pathlab;
using namespace pathlab::grader;
namespace fs = std::filesystem;

const char* usage = R"(usage: grader [options]              grade the labs of this build
       grader make-references [options]  measure grader/references/ from the solutions

options
  --lab NAME          grade one lab: branching | uniform | importance | roulette
  --viewer PATH       the viewer whose labs are graded (default: the one beside grader)
  --solution-viewer PATH
                      the viewer whose --solution is the reference (default: --viewer)
  --scenes DIR        also grade on every .ecs in DIR (references measured on the fly)
  --rubric FILE       points and thresholds (default: grader/rubric.json)
  --references DIR    stored references (default: grader/references)
  --seed N            seed base (default 1); a fail is re-checked on fresh seeds anyway
  --threads N         threads per render (default: all cores)
  --no-speed          skip the frame-rate check
  --json FILE --junit FILE --gradescope FILE --html DIR
                      reports (the terminal table is always printed)
)";

struct Arguments {
    std::string command = "grade";
    std::vector<Lab> labs{AllLabs.begin(), AllLabs.end()};
    std::string viewer, solutionViewer, scenesDir;
    std::string rubric = std::string(PATHLAB_GRADER_DIR) + "/rubric.json";
    std::string references = std::string(PATHLAB_GRADER_DIR) + "/references";
    std::string json, junit, gradescope, html;
    uint64_t seed = 1;
    int threads = 0;
    bool speed = true;
};

Arguments parse(int argc, char** argv) {
    Arguments a;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) throw InputError(std::string("option ") + argv[i] + " needs a value");
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "make-references" && i == 1) a.command = arg;
        else if (arg == "--lab") {
            const std::string name = value(i);
            const auto lab = labFromName(name);
            if (!lab) throw InputError("option --lab expects branching, uniform, importance or roulette, got '" + name + "'");
            a.labs = {*lab};
        } else if (arg == "--viewer") a.viewer = value(i);
        else if (arg == "--solution-viewer") a.solutionViewer = value(i);
        else if (arg == "--scenes") a.scenesDir = value(i);
        else if (arg == "--rubric") a.rubric = value(i);
        else if (arg == "--references") a.references = value(i);
        else if (arg == "--seed") a.seed = std::stoull(value(i));
        else if (arg == "--threads") a.threads = std::stoi(value(i));
        else if (arg == "--no-speed") a.speed = false;
        else if (arg == "--json") a.json = value(i);
        else if (arg == "--junit") a.junit = value(i);
        else if (arg == "--gradescope") a.gradescope = value(i);
        else if (arg == "--html") a.html = value(i);
        else if (arg == "--help" || arg == "-h") a.command = "help";
        else throw InputError("unknown option '" + arg + "' (grader --help lists the options)");
    }
    if (a.viewer.empty()) a.viewer = (fs::read_symlink("/proc/self/exe").parent_path() / "viewer").string();
    if (a.solutionViewer.empty()) a.solutionViewer = a.viewer;
    for (const std::string& v : {a.viewer, a.solutionViewer})
        if (::access(v.c_str(), X_OK) != 0) throw InputError("viewer '" + v + "' is not an executable file");
    return a;
}

/// A progress bar with counts and ETA on standard error.
Progress progressBar(const std::string& what) {
    const auto start = std::chrono::steady_clock::now();
    const bool terminal = ::isatty(STDERR_FILENO);
    return [what, start, terminal](int done, int total) {
        // Redrawn in place on a terminal; in a log, a line at each quarter.
        if (!terminal && done != total && (4 * done / total == 4 * (done - 1) / total)) return;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const int width = 30, filled = width * done / std::max(total, 1);
        std::fprintf(stderr, terminal ? "\r%s [%s%s] %d/%d renders, ETA %.0f s   " : "%s [%s%s] %d/%d renders, ETA %.0f s\n", what.c_str(),
                     std::string(filled, '=').c_str(), std::string(width - filled, ' ').c_str(), done, total,
                     done > 0 ? elapsed / done * (total - done) : 0.0);
        if (done == total && terminal) std::fputc('\n', stderr);
    };
}

std::string modelPath(const std::string& name) { return std::string(PATHLAB_MODELS_DIR) + "/" + name + ".ecs"; }

int makeReferences(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    fs::create_directories(a.references);
    for (const std::string& scene : rubric.scenes) {
        const SceneReference ref = measureReference(a.solutionViewer, modelPath(scene), rubric, 40, 8,
                                                    scratch, progressBar(scene));
        saveReference(a.references, ref);
        std::printf("wrote %s/%s.json\n", a.references.c_str(), scene.c_str());
    }
    return 0;
}

int grade(const Arguments& a, const Rubric& rubric, const std::string& scratch) {
    const auto start = std::chrono::steady_clock::now();
    GraderSetup setup{a.viewer, a.solutionViewer, rubric, {}, scratch, a.seed, a.threads, a.speed};
    GradeReport report;
    for (const std::string& scene : rubric.scenes) {
        GradingScene s{modelPath(scene), {}, scene == "furnace", 0.5};
        try {
            s.reference = loadReference(a.references, scene, rubric);
        } catch (const InputError& e) {
            report.notes.push_back(std::string(e.what()) + "; measured on the fly instead");
            s.reference = measureReference(a.solutionViewer, s.path, rubric, 20, 4, scratch, progressBar(scene));
        }
        setup.scenes.push_back(std::move(s));
    }
    if (!a.scenesDir.empty()) {
        if (!fs::is_directory(a.scenesDir)) throw InputError("option --scenes: '" + a.scenesDir + "' is not a folder");
        std::vector<fs::path> hidden;
        for (const auto& entry : fs::directory_iterator(a.scenesDir))
            if (entry.path().extension() == ".ecs") hidden.push_back(entry.path());
        std::sort(hidden.begin(), hidden.end());
        for (const fs::path& path : hidden) {
            GradingScene s{path.string(), measureReference(a.solutionViewer, path.string(), rubric, 20, 4, scratch,
                                                           progressBar(path.stem().string())),
                           false, 0.5};
            setup.scenes.push_back(std::move(s));
        }
    }
    for (Lab lab : a.labs) {
        std::fprintf(stderr, "grading %s ...\n", std::string(labName(lab)).c_str());
        report.labs.push_back(gradeLab(setup, lab));
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    std::fputs(terminalReport(report, ::isatty(STDOUT_FILENO)).c_str(), stdout);
    if (!a.json.empty()) writeFileAtomically(a.json, jsonReport(report));
    if (!a.junit.empty()) writeFileAtomically(a.junit, junitReport(report));
    if (!a.gradescope.empty()) writeFileAtomically(a.gradescope, gradescopeReport(report));
    if (!a.html.empty()) writeHtmlReport(report, a.html);
    return report.score() == report.maxScore() ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    std::string scratch;
    int status = 2;
    try {
        const Arguments a = parse(argc, argv);
        if (a.command == "help") {
            std::fputs(usage, stdout);
            return 0;
        }
        const Rubric rubric = loadRubric(a.rubric);
        char pattern[] = "/tmp/pathlab-grader-XXXXXX";
        if (!::mkdtemp(pattern)) throw std::runtime_error("cannot make a scratch folder");
        scratch = pattern;
        status = a.command == "make-references" ? makeReferences(a, rubric, scratch) : grade(a, rubric, scratch);
    } catch (const InputError& e) {
        std::fprintf(stderr, "grader: %s\n", e.what());
        status = 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "grader: error: %s\n", e.what());
        status = 3;
    }
    if (!scratch.empty()) fs::remove_all(scratch);
    return status;
}
