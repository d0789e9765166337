#include "traversal_timing.h"

#include "pathlab/support/cpu_clock.h"
#include "pathlab/render/embree_rays.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pathlab::bench {

namespace {

/// Rays per task: enough that TBB's scheduling, and the two readings of the thread's CPU clock,
/// are lost in the traversal time.
constexpr size_t Grain = 1024;

/// Wall and CPU time of traversals.
struct Times {
    double seconds = 0, cpuSeconds = 0;
};

/// The least wall time and the least CPU time of `repeats` runs of `trace` over [0, count), after
/// `prepare` (untimed) each time. The CPU time is each task's own, read from its thread's clock
/// around its rays, so that a thread waiting for work is not counted; with the process's clock
/// (CpuClock::Process) it is the process's over the run.
template <typename Prepare, typename Trace>
Times leastTimes(tbb::task_arena& arena, size_t count, int repeats, Prepare prepare, Trace trace) {
    const bool perThread = cpuClock() == CpuClock::PerThread;
    Times best;
    for (int r = 0; r < repeats; ++r) {
        prepare();
        std::atomic<uint64_t> cpuNanoseconds{0};
        const double processBefore = processCpuSeconds();
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, count, Grain),
                              [&](const tbb::blocked_range<size_t>& range) {
                                  const double before = perThread ? threadCpuSeconds() : 0;
                                  for (size_t i = range.begin(); i != range.end(); ++i) trace(i);
                                  if (perThread)
                                      cpuNanoseconds.fetch_add(
                                          static_cast<uint64_t>(
                                              std::llround(1e9 * (threadCpuSeconds() - before))),
                                          std::memory_order_relaxed);
                              });
        });
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        const double cpuSeconds = perThread ? 1e-9 * static_cast<double>(cpuNanoseconds.load())
                                            : processCpuSeconds() - processBefore;
        best.seconds = r == 0 ? elapsed.count() : std::min(best.seconds, elapsed.count());
        best.cpuSeconds = r == 0 ? cpuSeconds : std::min(best.cpuSeconds, cpuSeconds);
    }
    return best;
}

} // namespace

TraversalTimes& TraversalTimes::operator+=(const TraversalTimes& o) {
    cameraRays += o.cameraRays;
    bounceRays += o.bounceRays;
    shadowRays += o.shadowRays;
    cameraSeconds += o.cameraSeconds;
    bounceSeconds += o.bounceSeconds;
    shadowSeconds += o.shadowSeconds;
    cameraCpuSeconds += o.cameraCpuSeconds;
    bounceCpuSeconds += o.bounceCpuSeconds;
    shadowCpuSeconds += o.shadowCpuSeconds;
    return *this;
}

TraversalTimes timeTraversal(const RenderScene& scene, const RayLog& log, int threads,
                             int repeats) {
    RTCScene embreeScene = scene.embreeScene();
    tbb::task_arena arena(threads);
    TraversalTimes times;

    // Camera rays and bounce rays apart: the renderer flags the first as coherent.
    std::vector<Ray> camera, bounce;
    for (const Ray& ray : log.closestHit)
        (ray.kind == RayKind::Camera ? camera : bounce).push_back(ray);
    std::vector<RTCRayHit> queries;
    const auto timeClosestHit = [&](const std::vector<Ray>& rays, bool coherent) {
        queries.resize(rays.size());
        return leastTimes(
            arena, rays.size(), repeats,
            [&] {
                for (size_t i = 0; i < rays.size(); ++i)
                    queries[i] = embree::closestHitQuery(rays[i]);
            },
            [&](size_t i) { embree::intersect1(embreeScene, queries[i], coherent); });
    };
    times.cameraRays = camera.size();
    const Times cameraTimes = timeClosestHit(camera, true);
    times.cameraSeconds = cameraTimes.seconds;
    times.cameraCpuSeconds = cameraTimes.cpuSeconds;
    times.bounceRays = bounce.size();
    const Times bounceTimes = timeClosestHit(bounce, false);
    times.bounceSeconds = bounceTimes.seconds;
    times.bounceCpuSeconds = bounceTimes.cpuSeconds;
    queries = {};

    std::vector<RTCRay> shadows(log.occlusion.size());
    times.shadowRays = shadows.size();
    const Times shadowTimes = leastTimes(
        arena, shadows.size(), repeats,
        [&] {
            for (size_t i = 0; i < shadows.size(); ++i)
                shadows[i] = embree::occlusionQuery(log.occlusion[i].from, log.occlusion[i].to);
        },
        [&](size_t i) { embree::occluded1(embreeScene, shadows[i]); });
    times.shadowSeconds = shadowTimes.seconds;
    times.shadowCpuSeconds = shadowTimes.cpuSeconds;
    return times;
}

} // namespace pathlab::bench
