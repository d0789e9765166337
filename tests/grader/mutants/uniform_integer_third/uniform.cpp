// Mutant: lab 2 written out, TODO lines removed, whose pick probability is the integer division
// 1 / 3, which is 0: no component is ever picked, so it renders direct light only, as the stub
// does, although none of its steps is open.
#include "pathlab/lab.h"

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
    const float pickProbability = 1 / 3;
    const float u = ctx.sampler.get1D();

    // Trace the chosen one and divide by its probability (TODO lab2.4).
    const Material& m = hit.material;
    if (u < pickProbability && !isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) /
                    pickProbability;
    else if (u < 2 * pickProbability && !isBlack(m.Ks))
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) / pickProbability;
    else if (u < 3 * pickProbability && !isBlack(m.Kt))
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) / pickProbability;
    return radiance;
}

} // namespace pathlab::uniform
