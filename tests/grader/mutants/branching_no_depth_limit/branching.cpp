// Mutant 'branching_no_depth_limit': the depth limit left out, so that in a closed scene the
// recursion never ends and overflows the stack within milliseconds A plausible student bug; the
// grader must fail it (see tests/grader/mutants.json), and the viewer names it as it crashes.
// Lab 1: the branching path tracer (handouts/01-branching.md).
#include "pathlab/lab.h"

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab1.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // (No depth limit: the recursion never ends where no ray leaves the scene.)

    // Every non-zero component, each with its own ray (TODOs lab1.3-lab1.5).
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
