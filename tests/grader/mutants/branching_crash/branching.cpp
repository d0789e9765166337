// Mutant 'branching_crash': dereferences a null pointer
// A plausible student bug; the grader must fail it (see tests/grader/mutants.json).
// Lab 1: the branching path tracer (handouts/01-branching.md).
#include "pathlab/lab.h"

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (depth == 1) {
        volatile int* nowhere = nullptr;
        *nowhere = 1; // crashes
    }
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab1.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // The depth limit: no bounce rays from a hit at maxDepth (TODO lab1.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Every non-zero component, each with its own ray (TODOs lab1.3-lab1.5).
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
