// Mutant 'uniform_cuts_corners_when_timed': correct for the first samples of a run, then stops
// bouncing. A correctness render (all 10 seeds of a 64x64 scene at 32 spp: 1.3 million camera
// rays) never reaches the switch; a timed render (256x256 at 48 spp: 3.1 million) does, and runs
// faster for it. The grader must not give speed points for that (see tests/grader/mutants.json).
// Lab 2: uniform selection of one component (handouts/02-uniform-pick.md).
#include "pathlab/lab.h"

#include <algorithm>
#include <atomic>

namespace pathlab::uniform {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static std::atomic<long> cameraRays{0};
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return radiance;
    // The cut corner: past 2 million camera rays in this process, no more bounces.
    if (depth == 0 && ++cameraRays > 2000000) return radiance;

    constexpr float pickProbability = 1.0f / 3.0f;
    const int component = std::min(static_cast<int>(ctx.sampler.get1D() * 3.0f), 2);
    const Material& m = hit.material;
    if (component == 0 && !isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) /
                    pickProbability;
    if (component == 1 && !isBlack(m.Ks))
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) / pickProbability;
    if (component == 2 && !isBlack(m.Kt))
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) / pickProbability;
    return radiance;
}

} // namespace pathlab::uniform
