// Mutant: lab 4 that kept lab 3's depth limit before its roulette: paths end at ctx.maxDepth
// as well, so the image is the depth-limited one, darker than the unbiased reference.

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
    if (depth >= ctx.maxDepth) return radiance;
    if (ctx.sampler.get1D() >= ctx.continueProb) return radiance;

    // Importance selection of one component, as in lab 3 (TODO lab4.3).
    const Material& m = hit.material;
    const float diffuse = reduceMax(m.Kd), mirror = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
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
