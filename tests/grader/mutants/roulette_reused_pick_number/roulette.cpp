// Mutant 'roulette_reused_pick_number': one random pair for both the component pick and the
// diffuse direction (pick with uv.x, then diffuseRay(hit, uv)), so a diffuse bounce only ever
// has u.x < its pick probability (0.64 on mixed_surfaces' walls): part of the hemisphere only.
// A plausible student bug; the grader must fail it on mixed_surfaces (the furnaces cannot see it).
// Lab 4: Russian roulette instead of a depth limit (handouts/04-russian-roulette.md).
#include "pathlab/lab.h"

namespace pathlab::roulette {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab4.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // Russian roulette replaces the depth limit: go on with probability continueProb
    // (TODO lab4.2).
    if (ctx.sampler.get1D() >= ctx.continueProb) return radiance;

    // Importance selection of one component, as in lab 3 (TODO lab4.3).
    const Material& m = hit.material;
    const float diffuse = reduceMax(m.Kd), mirror = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
    const float total = diffuse + mirror + transmit;
    if (total < 0.01f) return radiance;

    // Divide by both probabilities: the pick's and roulette's (TODO lab4.4).
    const Vec2 uv = ctx.sampler.get2D();
    const float u = uv.x * total;
    Color traced;
    if (u < diffuse)
        traced = m.Kd * pathTrace(diffuseRay(hit, uv), depth + 1, ctx) * (total / diffuse);
    else if (u < diffuse + mirror)
        traced = m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        traced = m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    radiance += traced / ctx.continueProb;
    return radiance;
}

} // namespace pathlab::roulette
