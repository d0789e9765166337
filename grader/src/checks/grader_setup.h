#pragma once
/// What the checks of one lab are given: the labs to run, the rubric, the scenes and their
/// references, and how to time and limit the renders. What they return is check_result.h.

#include "checks/expectation.h"
#include "checks/race_report.h"
#include "checks/local_speed_estimate.h"
#include "checks/rubric.h"
#include "common/by_lab.h"
#include "diagnosis/diagnosis.h"
#include "isolation/render_run.h"

#include "pathlab/render/lab_parameters.h"
#include "pathlab/render/lab_registry.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// A scene to grade on: its .ecs path and what it is compared with.
struct GradingScene {
    std::string path;
    SceneReference reference;
    std::optional<FurnaceModel> furnace; ///< a furnace's analytic values, for the diagnosis
    /// Rendered at these instead of the rubric's parameters (the parameter check).
    std::optional<LabParameters> parameters;
    /// What feedback calls it: the scene's name, or "hidden scene N" for one of the instructor's
    /// hidden scenes, of which feedback says pass or fail and a likely cause, never the name,
    /// the images or the tiles (unless the instructor reveals them).
    std::string name;
    bool hidden = false;
    /// The labs graded on it; empty: every lab (the glossy furnace is for the labs that write a
    /// lobe alone: labs 1-4 grade as they did before it).
    std::vector<Lab> labs;

    bool grades(Lab lab) const {
        return labs.empty() || std::find(labs.begin(), labs.end(), lab) != labs.end();
    }
};

/// How the frame-rate check keeps its timings fair on a machine that does other work meanwhile
/// (grader batch): the timed runs take cores of their own, one grading at a time.
struct TimingPolicy {
    std::vector<int> cpus; ///< the timed runs' cores (empty: wherever the runners run)
    std::string lockFile;  ///< held for a lab's whole interleaved series (empty: no lock)
    int threads = 0;       ///< threads per timed render (0: as the other renders)
};

struct GraderSetup {
    LabRunner student;  ///< runs the labs being graded
    LabRunner solution; ///< runs the reference solutions
    TimingPolicy timing;
    Rubric rubric;
    std::vector<GradingScene> scenes;
    std::string scratch;
    uint64_t seedBase = 1;
    int threads = 0;
    bool measureSpeed = true;
    /// The build has the reference solutions (the kit, the instructor's graders); a student's
    /// release has not: there lab 6's strategies alone are the lab's own (strategy_noise.h).
    bool solutionsAvailable = true;
    /// A build without the solutions cannot check speed (measureSpeed false), but it still times
    /// the student's labs, for the speed ratios between them; the reference's ratios then come
    /// from the stored figures (lab_figures.json, by lab; 0 where none).
    bool timeWithoutSolutions = false;
    StoredSolutionSpeed storedSolution;
    /// The kit's own cost of a ray on this machine (kit_ray_cost.h), which carries the stored
    /// samples per CPU-second here; 0: not measured.
    double kitCpuSecondsPerRay = 0;
    /// The race check of a submitted lab (race_check.h), made once its correctness renders
    /// finished; its finding enters the correctness verdict (race_verdict.h). Empty: none.
    std::function<RaceFinding(Lab)> raceCheck;
};

} // namespace pathlab::grader
