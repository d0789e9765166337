#pragma once
/// The tile-parallel render loop: camera rays in, pathTrace per sample, sums into the buffer.

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/color.h"
#include "pathlab/render/lab_parameters.h"
#include "pathlab/render/nonfinite_sample.h"
#include "pathlab/render/ray_counters.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/render/render_progress.h"
#include "pathlab/render/render_scene.h"

#include <atomic>
#include <cstdint>
#include <memory>

namespace pathlab {

class PathContext;
struct Ray;

/// A lab's estimator: the radiance arriving along `ray` (lab.h).
using PathTraceFunction = Color (*)(const Ray& ray, int depth, PathContext& ctx);

/// Renders passes of samples into an AccumulationBuffer with TBB over square tiles. Each sample
/// draws its random numbers from a stream keyed by (seed, pixel, sample index), so the image does
/// not depend on the number of threads or the order tiles run in.
class Renderer {
public:
    /// `threads` = 0 uses defaultThreads().
    Renderer(const RenderScene& scene, int threads);
    /// Every core this process may use: TBB's count, which a Slurm job's affinity mask limits.
    static int defaultThreads();
    ~Renderer();

    /// Adds `spp` samples to every pixel of `buffer`, traced with `pathTrace`. If `cancel` is
    /// given and becomes true, the remaining tiles are skipped and false is returned: the buffer
    /// then holds part of a pass and must be cleared before it is shown. If `log` is given, the
    /// pass's rays are appended to it in tile order.
    bool renderPass(AccumulationBuffer& buffer, const Camera& camera, PathTraceFunction pathTrace,
                    const LabParameters& parameters, uint64_t seed, int spp,
                    const std::atomic<bool>* cancel = nullptr, RayLog* log = nullptr);

    /// Rays traced by all passes since construction (or the last resetCounts()).
    RayCounters rayCounters() const { return counters_; }
    /// The first non-finite sample of those passes, by sample index and pixel, if any.
    const std::optional<NonfiniteSample>& firstNonfinite() const { return firstNonfinite_; }
    void resetCounts() {
        counters_ = {};
        firstNonfinite_.reset();
        cpuSeconds_ = processCpuSeconds_ = 0;
    }
    /// The CPU time the render threads spent rendering tiles in those passes (cpu_clock.h): the
    /// work of the passes, which other programs on the machine change little. Where the clock is
    /// the process's (CpuClock::Process), the process's CPU time over the passes.
    double cpuSeconds() const { return cpuSeconds_; }
    /// The whole process's CPU time over the passes: above cpuSeconds() by the work of threads
    /// that are not the renderer's (a lab that starts its own, the window's drawing).
    double processCpuSeconds() const { return processCpuSeconds_; }
    int threads() const { return threads_; }
    /// Renders the tiles from the last to the first (or back in order). Each sample's random
    /// numbers come from its own stream, so the image does not change; a lab that draws random
    /// numbers of its own, or keeps state between samples, renders another image.
    void setReverseTiles(bool reverse) { reverseTiles_ = reverse; }
    /// How far the passes have got, for another thread to read while one runs.
    const RenderProgress& progress() const { return progress_; }

    /// Pixels per tile side: 1024 tiles at 512x512, 8160 at 1920x1080. 8 to 64 measured alike
    /// on 2 cores (`make bench`, Scaling).
    static constexpr int TileSize = 16;
    /// Another tile size, for the benchmark's comparison of them: the image is the same.
    void setTileSize(int pixels) { tileSize_ = pixels; }

private:
    struct Arena;
    class FirstFailure;
    class PassTiles;
    /// The CPU time a pass took: the whole process's, and its render threads' (the process's
    /// where the system has no clock per thread).
    struct PassCpuTime {
        double process = 0, threads = 0;
    };
    /// Renders every tile on the arena's threads; a lab's exception is kept in `failure`.
    PassCpuTime renderTilesInParallel(PassTiles& tiles, const std::atomic<bool>* cancel,
                                      FirstFailure& failure);

    const RenderScene& scene_;
    int threads_;
    std::unique_ptr<Arena> arena_;
    RayCounters counters_;
    std::optional<NonfiniteSample> firstNonfinite_;
    double cpuSeconds_ = 0, processCpuSeconds_ = 0;
    bool reverseTiles_ = false;
    int tileSize_ = TileSize;
    RenderProgress progress_;
};

} // namespace pathlab
