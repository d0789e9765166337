#pragma once
/// How fast a lab renders, measured as the viewer renders: whole passes over the image.

#include "pathlab/camera.h"
#include "pathlab/lab_parameters.h"
#include "pathlab/lab_registry.h"
#include "pathlab/renderer.h"
#include "pathlab/ray_counters.h"
#include "pathlab/ray_log.h"
#include "pathlab/render_scene.h"

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

/// The fastest timed pass.
struct RenderTiming {
    double seconds = 0;    ///< of that pass
    long long samples = 0; ///< of that pass: width × height × spp
    RayCounters rays;      ///< of that pass

    double samplesPerSecond() const { return seconds > 0 ? samples / seconds : 0; }
    double intersectPerSecond() const { return seconds > 0 ? rays.intersect / seconds : 0; }
    double occludedPerSecond() const { return seconds > 0 ? rays.occluded / seconds : 0; }
    double raysPerSecond() const { return seconds > 0 ? rays.total() / seconds : 0; }
};

/// One warm-up pass, then `passes` timed passes of `spp` samples per pixel with `threads`
/// threads, each added to the same image as the viewer's window does; the fastest pass counts.
RenderTiming timeRender(const RenderJob& job, int spp, int passes, int threads,
                        int tileSize = Renderer::TileSize);

/// The rays of one pass of one sample per pixel, in the order they were traced.
RayLog recordRays(const RenderJob& job, int threads);

} // namespace pathlab::bench
