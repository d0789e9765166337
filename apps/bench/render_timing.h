#pragma once
/// How fast a lab renders, measured as the viewer renders: whole passes over the image.

#include "pathlab/scene_io/camera.h"
#include "pathlab/render/lab_parameters.h"
#include "pathlab/render/lab_registry.h"
#include "pathlab/render/renderer.h"
#include "pathlab/render/ray_counters.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/render/render_scene.h"

namespace pathlab::bench {

/// What to render: a lab's pathTrace on a scene, at a size.
struct RenderJob {
    const RenderScene& scene;
    const Camera& camera;
    PathTraceFunction pathTrace;
    LabParameters parameters;
    int width, height;
};

/// The camera a scene is measured through: its own, or the one the viewer frames the model with.
Camera sceneCamera(const RenderScene& scene, int width, int height);

/// A reference solution's render of `scene` through `camera`.
RenderJob solutionJob(const RenderScene& scene, const Camera& camera, Lab lab,
                      const LabParameters& parameters, int width, int height);

/// Which of the timed passes counts.
enum class PassChoice {
    LeastCpuTime,  ///< speed: the work of a pass, which other programs on the machine change little
    LeastWallTime, ///< waiting: how soon a pass is done (thread scaling, tile sizes)
};

/// The timed pass that counts, by both clocks.
struct RenderTiming {
    double seconds = 0;    ///< wall time of that pass
    double cpuSeconds = 0; ///< the render threads' CPU time in that pass (Renderer::cpuSeconds)
    /// The whole process's CPU time in that pass: comparable with another program's CPU time.
    double processCpuSeconds = 0;
    int threads = 0;
    long long samples = 0; ///< of that pass: width × height × spp
    RayCounters rays;      ///< of that pass

    double samplesPerSecond() const { return perSecond(samples, seconds); }
    double intersectPerSecond() const { return perSecond(rays.intersect, seconds); }
    double occludedPerSecond() const { return perSecond(rays.occluded, seconds); }
    double raysPerSecond() const { return perSecond(rays.total(), seconds); }
    double samplesPerCpuSecond() const { return perSecond(samples, cpuSeconds); }
    double intersectPerCpuSecond() const { return perSecond(rays.intersect, cpuSeconds); }
    double occludedPerCpuSecond() const { return perSecond(rays.occluded, cpuSeconds); }
    double raysPerCpuSecond() const { return perSecond(rays.total(), cpuSeconds); }

    static double perSecond(double count, double seconds) {
        return seconds > 0 ? count / seconds : 0;
    }
};

/// One warm-up pass, then `passes` timed passes of `spp` samples per pixel with `threads`
/// threads, each added to the same image as the viewer's window does; the pass with the least
/// time by `choice`'s clock counts.
RenderTiming timeRender(const RenderJob& job, int spp, int passes, int threads,
                        int tileSize = Renderer::TileSize,
                        PassChoice choice = PassChoice::LeastCpuTime);

/// The rays of one pass of one sample per pixel, in the order they were traced.
RayLog recordRays(const RenderJob& job, int threads);

} // namespace pathlab::bench
