// Mutant 'branching_mirror_for_glass': traces a mirror ray for the Kt component, where glass
// refracts. A plausible student bug: the furnaces cannot see it (any direction there finds the
// same light); the grader's refraction check and the lab tests' view through glass must name
// TODO lab1.5 (see tests/grader/mutants.json and tests/estimators/CMakeLists.txt). Lab 1:
// branching (handouts/01-branching.md).
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

    // The depth limit: no bounce rays from a hit at maxDepth (TODO lab1.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Every non-zero component, each with its own ray (TODOs lab1.3-lab1.5).
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
