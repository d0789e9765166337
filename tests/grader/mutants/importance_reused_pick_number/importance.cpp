// Mutant 'importance_reused_pick_number': one random pair for both the component pick and the
// diffuse direction (pick with uv.x, then diffuseRay(hit, uv)), so a diffuse bounce only ever
// has u.x < its pick probability (0.64 on mixed_surfaces' walls): part of the hemisphere only.
// A plausible student bug; the grader must fail it on mixed_surfaces (the furnaces cannot see it).
// Lab 3: importance selection of one component (handouts/03-importance-pick.md).
#include "pathlab/lab.h"

namespace pathlab::importance {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab3.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // The depth limit (TODO lab3.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Probabilities proportional to each component's strength; stop on a near-black surface
    // (TODO lab3.3).
    const Material& m = hit.material;
    const float diffuse = reduceMax(m.Kd), mirror = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
    const float total = diffuse + mirror + transmit;
    if (total < 0.01f) return radiance;

    // Trace the chosen component and divide by its probability (TODO lab3.4).
    const Vec2 uv = ctx.sampler.get2D();
    const float u = uv.x * total;
    if (u < diffuse)
        radiance += m.Kd * pathTrace(diffuseRay(hit, uv), depth + 1, ctx) * (total / diffuse);
    else if (u < diffuse + mirror)
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    return radiance;
}

} // namespace pathlab::importance
