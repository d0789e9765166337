// Mutant 'roulette_specular_no_weight': divides a continued path by continueProb in the diffuse
// branch only; the mirror and refraction branches forget it. A plausible student bug; the grader
// and the lab tests must name the branches that forget 1/continueProb (see
// tests/grader/mutants.json and tests/estimators/CMakeLists.txt). Lab 4: Russian roulette
// (handouts/04-russian-roulette.md).
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
    const float u = ctx.sampler.get1D() * total;
    if (u < diffuse)
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                    (total / diffuse) / ctx.continueProb;
    else if (u < diffuse + mirror)
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    return radiance;
}

} // namespace pathlab::roulette
