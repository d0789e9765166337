#include "traversal_timing.h"

#include "pathlab/embree_rays.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace pathlab::bench {

namespace {

/// Rays per task: enough that TBB's scheduling is lost in the traversal time.
constexpr size_t Grain = 1024;

/// The fastest of `repeats` runs of `trace` over [0, count), after `prepare` (untimed) each time.
template <typename Prepare, typename Trace>
double fastest(tbb::task_arena& arena, size_t count, int repeats, Prepare prepare, Trace trace) {
    double best = 0;
    for (int r = 0; r < repeats; ++r) {
        prepare();
        const auto start = std::chrono::steady_clock::now();
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, count, Grain),
                              [&](const tbb::blocked_range<size_t>& range) {
                                  for (size_t i = range.begin(); i != range.end(); ++i) trace(i);
                              });
        });
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        best = r == 0 ? elapsed.count() : std::min(best, elapsed.count());
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
        return fastest(
            arena, rays.size(), repeats,
            [&] {
                for (size_t i = 0; i < rays.size(); ++i)
                    queries[i] = embree::closestHitQuery(rays[i]);
            },
            [&](size_t i) { embree::intersect1(embreeScene, queries[i], coherent); });
    };
    times.cameraRays = camera.size();
    times.cameraSeconds = timeClosestHit(camera, true);
    times.bounceRays = bounce.size();
    times.bounceSeconds = timeClosestHit(bounce, false);
    queries = {};

    std::vector<RTCRay> shadows(log.occlusion.size());
    times.shadowRays = shadows.size();
    times.shadowSeconds = fastest(
        arena, shadows.size(), repeats,
        [&] {
            for (size_t i = 0; i < shadows.size(); ++i)
                shadows[i] = embree::occlusionQuery(log.occlusion[i].from, log.occlusion[i].to);
        },
        [&](size_t i) { embree::occluded1(embreeScene, shadows[i]); });
    return times;
}

} // namespace pathlab::bench
