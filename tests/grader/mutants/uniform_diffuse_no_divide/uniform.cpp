// Mutant 'uniform_diffuse_no_divide': divides by the pick probability 1/3 in the mirror and
// refraction branches, not in the diffuse one. A plausible student bug; the grader must name
// the branch, not a factor of 1/pi, whose furnace values are close (see
// tests/grader/mutants.json). Lab 2: uniform selection of one component
// (handouts/02-uniform-pick.md).
#include "pathlab/lab.h"

#include <algorithm>

namespace pathlab::uniform {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab2.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // The depth limit (TODO lab2.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Pick one of the three components, each with probability 1/3 (TODO lab2.3).
    constexpr float pickProbability = 1.0f / 3.0f;
    const int component = std::min(static_cast<int>(ctx.sampler.get1D() * 3.0f), 2);

    // Trace the chosen one and divide by its probability (TODO lab2.4). A zero component
    // contributes nothing, and its ray is not worth tracing.
    const Material& m = hit.material;
    if (component == 0 && !isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (component == 1 && !isBlack(m.Ks))
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) / pickProbability;
    if (component == 2 && !isBlack(m.Kt))
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) / pickProbability;
    return radiance;
}

} // namespace pathlab::uniform
