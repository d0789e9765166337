// Mutant 'uniform_cuts_corners_when_timed': correct for the first samples of a run, then stops
// bouncing. The correctness renders are short enough never to reach the switch; the longer
// timed renders do, and run faster for it. The grader must not give speed points for that
// (see tests/grader/mutants.json).
// Lab 2: uniform selection of one component (handouts/02-uniform-pick.md).
#include "pathlab/lab.h"

#include <algorithm>

namespace pathlab::uniform {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    static thread_local long cameraRays = 0;
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return radiance;
    // The cut corner: past 300,000 camera rays on this thread, no more bounces.
    if (depth == 0 && ++cameraRays > 300000) return radiance;

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
