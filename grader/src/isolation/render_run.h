#pragma once
/// One render of one lab through a viewer process: the grader never runs lab code in its own
/// process, so a crash, a hang or a runaway allocation costs one run, not the grading.

#include "common/by_lab.h"
#include "isolation/process_runner.h"
#include "isolation/sandbox.h"

#include "pathlab/render/lab_registry.h"
#include "pathlab/render/render_identity.h"
#include "pathlab/render/ray_counters.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pathlab::grader {

/// Whose labs a render runs, and how it is started.
struct LabRunner {
    std::string viewer; ///< the viewer binary
    /// With the labs linked into `viewer`: which set (--solution or not).
    Implementation implementation = Implementation::Student;
    /// When set, `viewer` is the submission viewer, run in the sandbox with lab L compiled into
    /// the shared library labLibraries[L] (grader batch, grader submission). A render loads the
    /// library of the lab it renders and no other, so a lab file that hangs, crashes or exits
    /// while it loads costs only its own lab.
    ByLab<std::string> labLibraries;
    SandboxPolicy sandbox; ///< for sandboxed runs
    std::vector<int> cpus; ///< for direct runs: the cores to use (empty: any)

    /// Any lab's library set: a submission that left a lab out has none for it, and must still
    /// run in the sandbox.
    bool sandboxed() const {
        return std::any_of(labLibraries.begin(), labLibraries.end(),
                           [](const std::string& library) { return !library.empty(); });
    }
    const std::string& libraryFor(Lab lab) const { return labLibraries[lab]; }
};

struct RenderRequest {
    const LabRunner* runner = nullptr;
    std::string scene; ///< .ecs path
    /// The lab, its parameters, the first seed and the size; the implementation is the
    /// runner's (requestedIdentity).
    RenderIdentity identity{Lab::Branching, Implementation::Student, {3, 0.8f}, 0, 64, 64};
    int spp = 16;
    int seeds = 1; ///< images for seeds identity.seed .. identity.seed+seeds-1, in one process
    int threads = 0;
    std::string scratch;       ///< a folder for the images and stats
    bool reverseTiles = false; ///< the viewer's --reverse-tiles
    /// The viewer's --inspect after the render, when `inspectSamples` > 0: the path inspector's
    /// JSON of pixel (inspectX, inspectY) is then in RenderResult::replayJson.
    int inspectX = 0, inspectY = 0, inspectSamples = 0;
};

/// The identity a request for `lab` by `runner` renders: its parameters, first seed and size.
RenderIdentity requestedIdentity(const LabRunner& runner, Lab lab, const LabParameters& parameters,
                                 uint64_t seed, int width, int height);

/// One seed's image, and where the viewer's --stats for it are. Those come from the lab's own
/// process, which could write anything there: points are earned by the images and the wall
/// clock alone. The ray counts explain (rays_per_sample.h), and can only cost a lab points: a
/// roulette lab whose paths do not lengthen with continueProb fails (path_length.h).
struct RenderedImage {
    std::vector<float> rgb; ///< linear RGB, top row first
    std::string statsFile;  ///< in the request's scratch folder, until the next render
    RayCounters rays;       ///< the stats' ray counts: for explanations, never a score alone
};

/// RenderResult::failureKind of a render whose image holds NaN or infinite values.
inline constexpr const char* NonfiniteRadianceFailure = "NaN or infinite radiance";

struct RenderResult {
    bool ok = false;
    std::string failure;     ///< why not ok, in words for the student
    std::string failureKind; ///< the same in a few words ("crashed", "time limit", ...)
    /// What the lab printed, apart from `failure` (which quotes its last lines): for a scene the
    /// student may not see, nothing of either is shown (correctness_check.cpp).
    std::string outputNote; ///< ProcessOutcome::outputNote, when it printed past the limit
    ProcessOutcome process;
    int width = 0, height = 0;
    std::vector<RenderedImage> images; ///< one per seed, in order
    std::string replayJson;            ///< the path inspector's, when the request asked for it

    const std::vector<float>& image() const { return images.front().rgb; }
};

/// What one render may take. Its work is limited in CPU time and in progress, which the machine's
/// load does not change, so a correct lab is never stopped because other work shares the cores;
/// wall-clock time only as the last resort.
struct RenderLimits {
    double cpuSecondsPerThread = 30; ///< the render's CPU time over its threads
    double stallSeconds = 15;        ///< the viewer's watchdog: no sample finished for this long
    double wallSeconds = 300;        ///< the last resort, whatever the load
    long long memoryBytes = 4LL << 30;
};

/// Runs one viewer process for all the request's seeds; the limits hold for that process.
RenderResult renderLab(const RenderRequest& request, const RenderLimits& limits);

/// A run of the viewer for one of its tools other than a render (--lobe-dump, --pick-test) with
/// a lab of `runner`, in the sandbox where the runner has one.
struct LabToolRequest {
    const LabRunner* runner = nullptr;
    Lab lab = Lab::Branching;
    std::string scene;                  ///< .ecs path, or "" for a tool that needs none
    std::vector<std::string> arguments; ///< the tool's; `collect` among them names its file
    std::string collect;                ///< the file it writes, read back ("": none)
    std::string scratch;
    /// Which outcomes are a finished run (the pick test ends with 1 when the picks differ).
    std::function<bool(const ProcessOutcome&)> succeeded = [](const ProcessOutcome& p) {
        return p.succeeded();
    };
};

/// What it gave: the file and the output, as the lab's process wrote them (judged by the
/// grader, never trusted), or why it failed in a render's words.
struct LabToolRun {
    bool ok = false;
    std::string failure, failureKind; ///< as RenderResult's
    std::string bytes;                ///< the collected file
    std::string output;               ///< standard output and error
};

LabToolRun runLabTool(const LabToolRequest& request, const RenderLimits& limits);

/// viewer --lobe-dump at `seed`: what a lab's lobe routines gave for the grader's inputs
/// (pathlab/warp/phong_lobe_check.h judges them).
LabToolRun dumpLobe(const LabRunner& runner, Lab lab, uint64_t seed, const std::string& scratch,
                    const RenderLimits& limits);

/// A scene's files as a sandboxed render sees them: under /scene, laid out as on the host
/// relative to the .ecs, so that no path of the host shows; `ecs` is the .ecs inside.
struct SandboxedScene {
    std::string ecs;
    std::vector<std::pair<std::string, std::string>> files; ///< host path, path inside
};
SandboxedScene sandboxedScene(const std::string& ecsPath);

/// Means of the image and of its tiles × tiles regions, per channel: region 0 is the whole
/// image, then the tiles row by row. Returned flat: [region][channel].
std::vector<double> regionMeans(const std::vector<float>& image, int width, int height, int tiles);

} // namespace pathlab::grader
