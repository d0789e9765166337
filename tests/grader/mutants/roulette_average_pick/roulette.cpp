// Mutant 'roulette_average_pick': strengths by the channel average instead of reduceMax, used
// for the pick and for the division alike. Not a bug: any probabilities that are positive where
// a component reflects give an unbiased estimator (handouts/02-uniform-pick.md), so the grader
// must pass its correctness, on coloured materials too; only its noise may differ.
// Lab 4: Russian roulette instead of a depth limit (handouts/04-russian-roulette.md).
#include "pathlab/lab.h"

namespace pathlab::roulette {

namespace {

/// The mean of the three channels.
float channelAverage(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }

} // namespace

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

    // Importance selection of one component by its channel average (TODO lab4.3).
    const Material& m = hit.material;
    const float diffuse = channelAverage(m.Kd), mirror = channelAverage(m.Ks),
                transmit = channelAverage(m.Kt);
    const float total = diffuse + mirror + transmit;
    if (total < 0.01f) return radiance;

    // Divide by both probabilities: the pick's and roulette's (TODO lab4.4).
    const float u = ctx.sampler.get1D() * total;
    Color traced;
    if (u < diffuse)
        traced = m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                 (total / diffuse);
    else if (u < diffuse + mirror)
        traced = m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        traced = m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    radiance += traced / ctx.continueProb;
    return radiance;
}

} // namespace pathlab::roulette
