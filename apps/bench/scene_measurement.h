#pragma once
/// One scene's figures: Embree's raw traversal rates and each reference solution's speed.

#include "bench_scene.h"
#include "render_timing.h"
#include "traversal_timing.h"

#include <string>
#include <vector>

namespace pathlab::bench {

/// A reference solution, rendered and replayed with one thread and with all threads.
struct SolutionFigures {
    Lab lab;
    RenderTiming render, renderOneThread;
    TraversalTimes raw, rawOneThread; ///< Embree alone on the rays this solution traced

    /// The render's rays per CPU-second over Embree's alone per CPU-second on the same rays: the
    /// share of the render's time that is Embree's traversal. By CPU time, which other programs
    /// on the machine change little.
    double efficiency() const {
        return ratio(render.raysPerCpuSecond(), raw.mixRatePerCpuSecond());
    }
    double efficiencyOneThread() const {
        return ratio(renderOneThread.raysPerCpuSecond(), rawOneThread.mixRatePerCpuSecond());
    }
    /// The same share by wall-clock time: near efficiency() on an idle machine; on a busy one it
    /// moves with the load during each of the two runs it divides.
    double wallClockEfficiency() const { return ratio(render.raysPerSecond(), raw.mixRate()); }
    double wallClockEfficiencyOneThread() const {
        return ratio(renderOneThread.raysPerSecond(), rawOneThread.mixRate());
    }
    /// Samples/s with all threads over samples/s with one: wall-clock time, as scaling is about
    /// how soon an image is done.
    double scaling() const {
        return ratio(render.samplesPerSecond(), renderOneThread.samplesPerSecond());
    }
    static double ratio(double a, double b) { return b > 0 ? a / b : 0; }
};

/// What to measure on a scene.
struct SceneSettings {
    int width, height, spp, passes, threads;
    LabParameters parameters;
};

struct SceneFigures {
    std::string name;
    size_t triangles = 0;
    SceneSettings settings; ///< what it was measured at
    std::vector<SolutionFigures> solutions;

    /// Embree alone on the rays of all solutions together, by kind.
    TraversalTimes raw() const;
    TraversalTimes rawOneThread() const;
};

/// Times every reference solution on `scene` and replays the rays each one traced.
SceneFigures measureScene(const BenchScene& scene, const SceneSettings& settings);

} // namespace pathlab::bench
