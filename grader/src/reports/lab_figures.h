#pragma once
/// The figures a student writes in the lab notebook (handouts/00-setup.md): each estimator's
/// frame rate, samples per CPU-second, noise and efficiency on the labs' scene at 512×512 after
/// 64 samples per pixel, from the viewer's --stats of a headless render (the same figures its
/// panel shows). The frame rate is wall-clock time, what a person waits for; the ratios between
/// labs are taken of samples per CPU-second and of the efficiency per CPU-second, which other
/// programs on the machine change little.
/// `grader --report` measures the student's labs; `grader make-references` stores the reference
/// solutions' in grader/references/lab_figures.json, with the machine they were measured on,
/// so that a student without the solutions compares ratios with the reference's.

#include "checks/rays_per_sample.h"
#include "checks/rubric.h"
#include "common/by_lab.h"
#include "isolation/render_run.h"

#include <map>
#include <string>
#include <vector>

namespace pathlab::grader {

/// One row of the notebook: a lab at one continueProb.
struct NotebookEstimator {
    std::string key;   ///< "branching", "uniform", "importance", "roulette", "roulette_graded"
    std::string label; ///< for tables: "roulette, continueProb 0.8 (as graded)"
    Lab lab;
    float continueProb;
};

/// The notebook's rows for `labs` in order: a lab that ends paths by roulette (lab 4) twice, at
/// its default continueProb 0.1 and at the rubric's (graded) one.
std::vector<NotebookEstimator> notebookEstimators(const std::vector<Lab>& labs,
                                                  const Rubric& rubric);

/// The render a notebook figure comes from.
constexpr int NotebookSize = 512, NotebookSpp = 64;
/// Lab 4's rows are rendered at this spp too: handout 4 asks for the noise at 64 and at 256 spp,
/// which halves where the variance is finite and need not where it is not.
constexpr int NotebookLateSpp = 256;

struct EstimatorFigures {
    double samplesPerSecond = 0, framesPerSecond = 0; ///< wall-clock
    double samplesPerCpuSecond = 0; ///< the render threads' CPU time; 0: not measured
    double noise = 0;
    double efficiency = 0; ///< 1/(noise² × CPU seconds); 0: not measured
    double raysPerSample = 0;
    /// Why a figure above is less than it seems (a busy machine, CPU time outside the render
    /// threads), from --stats; empty when nothing was said.
    std::vector<std::string> notes;
    double noiseLate = 0;    ///< the noise after NotebookLateSpp; 0 where not measured
    std::string failure;     ///< why it could not be measured, in words; "" when measured
    std::string lateFailure; ///< why noiseLate could not be, when it was asked for
};

/// Whether a row's noise is also measured after NotebookLateSpp (lab 4's rows).
bool measuresLateNoise(const NotebookEstimator& row);

/// Where figures were measured.
struct Machine {
    std::string cpu, system, date, kitVersion;
    int cores = 0, threads = 0;
    double loadAverage = 0; ///< over the minute before the measurement started

    /// "Intel Xeon ... (2 cores, 2 threads), Debian GNU/Linux 12, load 0.3, 2026-12-01, PathLab
    /// 0.1.0"
    std::string describe() const;
};
Machine thisMachine(int threads);

struct LabFigures {
    Machine machine;
    std::map<std::string, EstimatorFigures> notebook; ///< by NotebookEstimator::key
    /// The grader's timed runs (the speed check's renders, speed_check.h): samples per
    /// CPU-second by lab, 0 where not measured. For the reference solutions these stand in for
    /// timing them next to the student's labs where the solutions are not part of the build.
    ByLab<double> timedSamplesPerSecond;
    /// Their rays per sample by kind, which no machine changes: what a lab's own are compared
    /// with where the solutions are not part of the build. Not known in older figures.
    ByLab<RaysPerSample> timedRays;
    bool timedRaysKnown = false;
    /// The kit's own cost of a ray on that machine (kit_ray_cost.h): how the timed figures are
    /// carried to another machine. 0: not stored.
    double kitCpuSecondsPerRay = 0;
};

/// Renders the notebook's rows with `runner`'s labs on the rubric's noise scene.
std::map<std::string, EstimatorFigures> measureNotebook(const LabRunner& runner,
                                                        const std::vector<NotebookEstimator>& rows,
                                                        const Rubric& rubric, int threads,
                                                        const std::string& scratch);

/// grader/references/lab_figures.json. Atomic.
void saveLabFigures(const std::string& path, const LabFigures& figures, const Rubric& rubric);
/// Replaces only the timed runs of the figures at `path` with `timed`'s (and its machine's),
/// keeping the notebook's. Atomic.
void replaceTimedRuns(const std::string& path, const LabFigures& timed, const Rubric& rubric);

/// What of the stored figures does not fit the rubric, in words ("" where it fits): the timed
/// runs (another speed scene, image size, seeds or samples per pixel) and the notebook (another
/// noise scene, max depth or continue probability). A missing or unreadable file: both.
struct FiguresStaleness {
    std::string timedRuns, notebook;
};
FiguresStaleness labFiguresStaleness(const std::string& path, const Rubric& rubric);
/// Throws InputError when missing, unreadable, or measured for other timed runs than the
/// rubric's (then timedSamplesPerSecond would not compare).
LabFigures loadLabFigures(const std::string& path, const Rubric& rubric);

} // namespace pathlab::grader
