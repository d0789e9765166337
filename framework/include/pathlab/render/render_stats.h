#pragma once
/// What a headless render measured, written as JSON for scripts and the grader.

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/color.h"
#include "pathlab/render/render_identity.h"
#include "pathlab/render/nonfinite_sample.h"
#include "pathlab/render/ray_counters.h"

#include <cstdint>
#include <optional>
#include <string>

namespace pathlab {

/// How a render compares with a --reference image (pathlab/images/relative_mse.h).
struct ReferenceFigures {
    std::string file;  ///< the reference as named on the command line
    double relMse = 0; ///< relativeMse, with relMseEpsilon
    double relMseEpsilon = 0;
    double relativeRmse = 0; ///< relativeRmse: RMSE over the reference's mean
};

struct RenderStats {
    std::string scene, lab, impl;
    int spp = 0, width = 0, height = 0;
    uint64_t seed = 0;
    int maxDepth = 0;
    float continueProb = 0;
    int threads = 0;
    double seconds = 0; ///< wall time of rendering alone (no loading, no writing)
    /// CPU time of the render threads rendering (Renderer::cpuSeconds): the measure of the
    /// render's work that the machine's load changes little; 0 where not measured.
    double cpuSeconds = 0;
    double processCpuSeconds = 0; ///< the whole process's over the render (Renderer's)
    std::string cpuClock;         ///< cpuClockName(): which clock measured cpuSeconds
    RayCounters rays;
    Color meanRadiance;
    Color meanVariance; ///< per-sample variance averaged over pixels, per channel
    int nonfinitePixels = 0;
    std::optional<NonfiniteSample> firstNonfinite; ///< where the first of those samples was
    double noise = 0; ///< imageNoise of the image (pathlab/images/image_noise.h)
    /// Frames per second of the window at this size, one sample per pixel per frame: the panel's
    /// median when the window measured it, samples/s ÷ (width × height) for a headless render.
    double framesPerSecond = 0;
    std::string framesPerSecondSource; ///< which of the two, in words
    /// With viewer -o ... --reference: the render against it (--stats' "reference").
    std::optional<ReferenceFigures> reference;

    double samplesPerSecond() const;
    double raysPerSecond() const;
    /// Samples per CPU-second of the render threads: the figure to compare between labs and
    /// machines' runs, which other programs on the machine change little. 0 where not measured.
    double samplesPerCpuSecond() const;
    /// The share of their cores the render threads had: cpuSeconds ÷ (seconds × threads). Well
    /// below 1, other processes shared the cores.
    double cpuShare() const;
    /// "the machine was busy: the render threads had 45% of their cores ...", or "" (also for a
    /// render of under half a second, mostly its threads starting).
    std::string busyNote() const;
    /// Why the CPU figure is not to be taken as precise ("" when it is): a render shorter than
    /// the clock's resolution allows, CPU time outside the render threads (threads of the lab's
    /// own), or a platform without per-thread clocks.
    std::string cpuNote() const;
    double efficiency() const; ///< renderEfficiency(noise, seconds)
    /// The efficiency for people: "2.44", or "undefined (no noise)" for a noiseless image.
    std::string efficiencyText() const;
    /// Empty when every sample was finite; otherwise one line for the student: how many pixels,
    /// and the first sample's pixel, sample index, lab, rays traced and radiance.
    std::string nonfiniteWarning() const;
};

/// What to say of one render: what was rendered (scene, lab, implementation, parameters, seed),
/// the image so far (its size, spp and summary), and what it cost. The frame rate is left to the
/// caller: the window measures its own, a headless render has setHeadlessFrameRate.
struct RenderedWhat : RenderIdentity {
    std::string scene;
};
/// What a render cost in CPU time (Renderer::cpuSeconds, processCpuSeconds); 0s: not measured.
struct CpuTimes {
    double renderThreads = 0, process = 0;
};
RenderStats renderStats(const RenderedWhat& what, const AccumulationBuffer& image, int threads,
                        double seconds, const RayCounters& rays,
                        const std::optional<NonfiniteSample>& firstNonfinite,
                        const CpuTimes& cpu = {});

/// The frame rate of a headless render: samples/s ÷ (width × height), what the window would show
/// at that size with one sample per pixel per frame.
void setHeadlessFrameRate(RenderStats& stats);

/// Writes `stats` as one JSON object: the fields the README lists under "--stats". Atomic, like
/// images.
void writeRenderStats(const std::string& path, const RenderStats& stats);

/// Reads what writeRenderStats wrote. Throws InputError naming the file and the field that is
/// missing or of the wrong type.
RenderStats readRenderStats(const std::string& path);

} // namespace pathlab
