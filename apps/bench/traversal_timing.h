#pragma once
/// Embree's raw speed: the rays a render traced, traced again with nothing else around them.

#include "pathlab/render/ray_log.h"
#include "pathlab/render/render_scene.h"

#include <cstddef>

namespace pathlab::bench {

/// How long Embree's traversal takes for each kind of recorded ray, alone: in wall time, and in
/// CPU time summed over the threads (each the least of the repeats by its own clock).
struct TraversalTimes {
    size_t cameraRays = 0, bounceRays = 0, shadowRays = 0;
    double cameraSeconds = 0, bounceSeconds = 0, shadowSeconds = 0;
    double cameraCpuSeconds = 0, bounceCpuSeconds = 0, shadowCpuSeconds = 0;

    size_t rays() const { return cameraRays + bounceRays + shadowRays; }
    double seconds() const { return cameraSeconds + bounceSeconds + shadowSeconds; }
    double cpuSeconds() const { return cameraCpuSeconds + bounceCpuSeconds + shadowCpuSeconds; }
    /// Rays per second for this mix of camera, bounce and shadow rays.
    double mixRate() const { return perSecond(rays(), seconds()); }
    /// Rays per CPU-second for the same mix: the rate other programs on the machine change little.
    double mixRatePerCpuSecond() const { return perSecond(rays(), cpuSeconds()); }
    TraversalTimes& operator+=(const TraversalTimes& o);

    static double perSecond(size_t rays, double seconds) {
        return seconds > 0 ? static_cast<double>(rays) / seconds : 0;
    }
};

/// Traces the rays of `log` through `scene`'s Embree scene with `threads` threads: the queries
/// are built beforehand and only the rtcIntersect1/rtcOccluded1 calls are timed, with the same
/// hints as the renderer (camera rays coherent). Each kind is timed `repeats` times; the least
/// wall time and the least CPU time count.
TraversalTimes timeTraversal(const RenderScene& scene, const RayLog& log, int threads, int repeats);

} // namespace pathlab::bench
