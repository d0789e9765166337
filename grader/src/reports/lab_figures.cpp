#include "reports/lab_figures.h"

#include "checks/run_limits.h"
#include "common/local_time.h"

#include "pathlab/images/image_noise.h"
#include "pathlab/support/input_error.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <optional>
#include <thread>

namespace pathlab::grader {

namespace {

/// The value of `key` ("model name", "PRETTY_NAME") in a Linux system file, or "".
std::string systemValue(const char* file, const std::string& key, char separator) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) != 0) continue;
        std::string value = line.substr(line.find(separator) + 1);
        value.erase(0, value.find_first_not_of(" \t\""));
        value.erase(value.find_last_not_of(" \t\"") + 1);
        return value;
    }
    return "";
}

/// A depth-limited lab's row in the notebook, as the handouts quote it: "uniform pick (lab 2)".
std::string notebookLabel(Lab lab) {
    const std::string number = " (lab " + std::to_string(labNumber(lab)) + ")";
    switch (lab) {
    case Lab::Uniform: return "uniform pick" + number;
    case Lab::Importance: return "importance pick" + number;
    case Lab::Glossy: return "glossy lobe" + number;
    case Lab::Mis: return "multiple importance sampling" + number;
    default: return std::string(labName(lab)) + number; // "branching (lab 1)"
    }
}

nlohmann::json machineJson(const Machine& m) {
    return {{"cpu", m.cpu},
            {"system", m.system},
            {"cores", m.cores},
            {"threads", m.threads},
            {"load_average", m.loadAverage},
            {"date", m.date},
            {"kit_version", m.kitVersion}};
}

} // namespace

std::vector<NotebookEstimator> notebookEstimators(const std::vector<Lab>& labs,
                                                  const Rubric& rubric) {
    std::vector<NotebookEstimator> rows;
    for (Lab lab : labs) {
        const std::string name(labName(lab)), number = std::to_string(labNumber(lab));
        if (isDepthLimited(lab)) {
            rows.push_back({name, notebookLabel(lab), lab, 0.1f});
            continue;
        }
        // A lab that ends paths by roulette: a row at the viewer's default continueProb, which
        // the handouts' figures use, and one as graded.
        rows.push_back(
            {name, name + ", continueProb 0.1 (lab " + number + "'s default)", lab, 0.1f});
        char graded[32];
        std::snprintf(graded, sizeof graded, "%g", rubric.continueProb);
        rows.push_back({name + "_graded", name + ", continueProb " + graded + " (as graded)", lab,
                        rubric.continueProb});
    }
    return rows;
}

std::string Machine::describe() const {
    char text[512];
    std::snprintf(text, sizeof text, "%s (%d cores, %d threads), %s, load %.1f, %s, PathLab %s",
                  cpu.c_str(), cores, threads, system.c_str(), loadAverage, date.c_str(),
                  kitVersion.c_str());
    return text;
}

Machine thisMachine(int threads) {
    Machine m;
    m.cpu = systemValue("/proc/cpuinfo", "model name", ':');
    if (m.cpu.empty()) m.cpu = "an unknown processor";
    m.system = systemValue("/etc/os-release", "PRETTY_NAME", '=');
    if (m.system.empty()) m.system = "an unknown system";
    m.cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    m.threads = threads > 0 ? threads : m.cores;
    double load[1] = {0};
    if (::getloadavg(load, 1) == 1) m.loadAverage = load[0];
    m.date = localTimeNow("%Y-%m-%d");
    m.kitVersion = PATHLAB_VERSION;
    return m;
}

bool measuresLateNoise(const NotebookEstimator& row) { return row.lab == Lab::Roulette; }

namespace {

/// One notebook render of `row` at `spp`: its stats, or why there are none.
std::optional<RenderStats> notebookRender(const LabRunner& runner, const NotebookEstimator& row,
                                          int spp, const Rubric& rubric, int threads,
                                          const std::string& scratch, std::string& failure) {
    const std::string scene = std::string(PATHLAB_MODELS_DIR) + "/" + rubric.noiseScene + ".ecs";
    // Longer than a grading render: 64 spp of 512×512 is 1000 times the pixels of one.
    const RenderLimits limits = renderLimits(rubric, 4.0 * spp / NotebookSpp);
    // Seed 0, the viewer's default: the command a student types gives these very numbers.
    const RenderRequest request{&runner,
                                scene,
                                requestedIdentity(runner, row.lab,
                                                  {rubric.maxDepth, row.continueProb}, 0,
                                                  NotebookSize, NotebookSize),
                                spp,
                                1,
                                threads,
                                scratch};
    const RenderResult result = renderLab(request, limits);
    if (!result.ok) {
        failure = result.failureKind;
        return std::nullopt;
    }
    try {
        return readRenderStats(result.images.front().statsFile);
    } catch (const InputError& e) {
        failure = "unreadable stats";
        return std::nullopt;
    }
}

} // namespace

std::map<std::string, EstimatorFigures> measureNotebook(const LabRunner& runner,
                                                        const std::vector<NotebookEstimator>& rows,
                                                        const Rubric& rubric, int threads,
                                                        const std::string& scratch) {
    std::map<std::string, EstimatorFigures> figures;
    for (const NotebookEstimator& row : rows) {
        EstimatorFigures& f = figures[row.key];
        const std::optional<RenderStats> s =
            notebookRender(runner, row, NotebookSpp, rubric, threads, scratch, f.failure);
        if (!s) continue;
        f.samplesPerSecond = s->samplesPerSecond();
        f.framesPerSecond = s->framesPerSecond;
        f.samplesPerCpuSecond = s->samplesPerCpuSecond();
        f.noise = s->noise;
        f.efficiency = renderEfficiency(s->noise, s->cpuSeconds);
        for (const std::string& note : {s->busyNote(), s->cpuNote()})
            if (!note.empty()) f.notes.push_back(note);
        f.raysPerSample = static_cast<double>(s->rays.total()) /
                          (static_cast<double>(s->spp) * s->width * s->height);
        if (!measuresLateNoise(row)) continue;
        const std::optional<RenderStats> late =
            notebookRender(runner, row, NotebookLateSpp, rubric, threads, scratch, f.lateFailure);
        if (late) f.noiseLate = late->noise;
    }
    return figures;
}

namespace {

/// The timed runs' part of lab_figures.json.
nlohmann::json timedRunsJson(const LabFigures& figures, const Rubric& rubric) {
    nlohmann::json timed = nlohmann::json::object(), timedSpp = nlohmann::json::object(),
                   rays = nlohmann::json::object();
    for (Lab lab : AllLabs) {
        const std::string name(labName(lab));
        timed[name] = figures.timedSamplesPerSecond[lab];
        timedSpp[name] = rubric.forLab(lab).correctnessSpp;
        const RaysPerSample& r = figures.timedRays[lab];
        rays[name] = {{"camera", r.camera}, {"bounce", r.bounce}, {"shadow", r.shadow}};
    }
    return {{"scene", rubric.speedScene},
            {"width", rubric.width},
            {"height", rubric.height},
            {"seeds", rubric.seeds},
            {"spp", timedSpp},
            {"runs", rubric.speedRuns},
            {"measure", "samples per CPU-second"},
            {"samples_per_second", timed},
            {"rays_per_sample", rays},
            {"kit_cpu_seconds_per_ray", figures.kitCpuSecondsPerRay}};
}

} // namespace

void saveLabFigures(const std::string& path, const LabFigures& figures, const Rubric& rubric) {
    nlohmann::json notebook = nlohmann::json::object();
    for (const auto& [key, f] : figures.notebook) {
        notebook[key] = {{"samples_per_second", f.samplesPerSecond},
                         {"frames_per_second", f.framesPerSecond},
                         {"samples_per_cpu_second", f.samplesPerCpuSecond},
                         {"noise", f.noise},
                         {"efficiency_per_cpu_second", f.efficiency},
                         {"rays_per_sample", f.raysPerSample},
                         {"notes", f.notes}};
        if (f.noiseLate > 0) notebook[key]["noise_late"] = f.noiseLate;
    }
    const nlohmann::json j = {
        {"made_by", "grader make-references"},
        {"about", "the reference solutions' lab-notebook figures (handouts/00-setup.md) and "
                  "their samples per CPU-second in the grader's timed runs (the correctness "
                  "renders of the speed scene), on the machine named; compare ratios between "
                  "labs with these, not absolute numbers; rays per sample are the same on any "
                  "machine"},
        {"machine", machineJson(figures.machine)},
        {"notebook",
         {{"scene", rubric.noiseScene},
          {"width", NotebookSize},
          {"height", NotebookSize},
          {"spp", NotebookSpp},
          {"late_spp", NotebookLateSpp},
          {"max_depth", rubric.maxDepth},
          {"graded_continue_prob", rubric.continueProb},
          {"estimators", notebook}}},
        {"timed_runs", timedRunsJson(figures, rubric)}};
    writeFileAtomically(path, j.dump(1) + "\n");
}

void replaceTimedRuns(const std::string& path, const LabFigures& timed, const Rubric& rubric) {
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    j["timed_runs"] = timedRunsJson(timed, rubric);
    // The notebook's figures stay those of the machine at the top; these are of this one.
    j["timed_runs"]["machine"] = machineJson(timed.machine);
    writeFileAtomically(path, j.dump(1) + "\n");
}

FiguresStaleness labFiguresStaleness(const std::string& path, const Rubric& rubric) {
    FiguresStaleness stale;
    try {
        const LabFigures figures = loadLabFigures(path, rubric);
        for (Lab lab : AllLabs)
            if (!(figures.timedSamplesPerSecond[lab] > 0))
                stale.timedRuns = "its timed runs are not the rubric's (the speed scene, image "
                                  "size, seeds or samples per pixel differ)";
        std::ifstream in(path);
        const nlohmann::json notebook = nlohmann::json::parse(in).at("notebook");
        const nlohmann::json continueProb = rubric.continueProb; // as saveLabFigures writes it
        if (notebook.value("scene", "") != rubric.noiseScene ||
            notebook.value("max_depth", 0) != rubric.maxDepth ||
            notebook.value("graded_continue_prob", nlohmann::json()) != continueProb)
            stale.notebook = "its notebook figures are not of the rubric's noise scene, max "
                             "depth or continue probability";
    } catch (const InputError& e) {
        stale.timedRuns = stale.notebook = e.what();
    } catch (const nlohmann::json::exception& e) {
        stale.timedRuns = stale.notebook = path + ": " + e.what();
    }
    return stale;
}

LabFigures loadLabFigures(const std::string& path, const Rubric& rubric) {
    std::ifstream in(path);
    if (!in)
        throw InputError(path +
                         ": no stored reference figures (grader make-references makes them)");
    LabFigures figures;
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        const nlohmann::json& m = j.at("machine");
        figures.machine = {m.at("cpu"),   m.at("system"),  m.at("date"),        m.at("kit_version"),
                           m.at("cores"), m.at("threads"), m.at("load_average")};
        // Figures stored before CPU time was measured have no samples per CPU-second and a
        // wall-clock efficiency: those are left at 0, not stored.
        for (const auto& [key, f] : j.at("notebook").at("estimators").items()) {
            EstimatorFigures& e = figures.notebook[key];
            e.samplesPerSecond = f.at("samples_per_second");
            e.framesPerSecond = f.at("frames_per_second");
            e.samplesPerCpuSecond = f.value("samples_per_cpu_second", 0.0);
            e.noise = f.at("noise");
            e.efficiency = f.value("efficiency_per_cpu_second", 0.0);
            e.raysPerSample = f.at("rays_per_sample");
            e.noiseLate = f.value("noise_late", 0.0);
            e.notes = f.value("notes", std::vector<std::string>{});
        }
        // Figures of other timed runs than the rubric's (another scene, size, seeds or samples,
        // or wall-clock time) would not compare: left at 0, unknown.
        const nlohmann::json& t = j.at("timed_runs");
        const bool sameRuns = t.at("scene") == rubric.speedScene && t.at("width") == rubric.width &&
                              t.at("height") == rubric.height &&
                              t.value("seeds", 0) == rubric.seeds &&
                              t.value("measure", "") == "samples per CPU-second";
        figures.timedRaysKnown = sameRuns && t.contains("rays_per_sample");
        figures.kitCpuSecondsPerRay = sameRuns ? t.value("kit_cpu_seconds_per_ray", 0.0) : 0.0;
        for (Lab lab : AllLabs) {
            const std::string name(labName(lab));
            // A lab added to the lab list since the figures were measured has none.
            if (!sameRuns || !t.at("spp").contains(name) ||
                t.at("spp").at(name) != rubric.forLab(lab).correctnessSpp) {
                figures.timedRaysKnown = false;
                continue;
            }
            figures.timedSamplesPerSecond[lab] = t.at("samples_per_second").at(name);
            if (figures.timedRaysKnown) {
                const nlohmann::json& r = t.at("rays_per_sample").at(name);
                figures.timedRays[lab] = {r.at("camera"), r.at("bounce"), r.at("shadow")};
            }
        }
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": " + e.what());
    }
    return figures;
}

} // namespace pathlab::grader
