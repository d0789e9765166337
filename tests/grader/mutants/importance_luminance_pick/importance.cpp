// Mutant 'importance_luminance_pick': strengths by luminance instead of reduceMax, used for the
// pick and for the division alike. Not a bug: any probabilities that are positive where a
// component reflects give an unbiased estimator (handouts/02-uniform-pick.md), so the grader
// must pass its correctness, on coloured materials too; only its noise may differ.
// Lab 3: importance selection of one component (handouts/03-importance-pick.md).
#include "pathlab/lab.h"

namespace pathlab::importance {

namespace {

/// Rec. 709 luminance: how bright a colour looks.
float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace

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

    // Probabilities proportional to each component's luminance; stop on a near-black surface
    // (TODO lab3.3).
    const Material& m = hit.material;
    const float diffuse = luminance(m.Kd), mirror = luminance(m.Ks), transmit = luminance(m.Kt);
    const float total = diffuse + mirror + transmit;
    if (total < 0.01f) return radiance;

    // Trace the chosen component and divide by its probability (TODO lab3.4).
    const float u = ctx.sampler.get1D() * total;
    if (u < diffuse)
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                    (total / diffuse);
    else if (u < diffuse + mirror)
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    return radiance;
}

} // namespace pathlab::importance
