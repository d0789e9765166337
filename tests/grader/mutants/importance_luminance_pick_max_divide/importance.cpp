// Mutant 'importance_luminance_pick_max_divide': picks a component with probabilities from its
// luminance but divides by the probability from reduceMax, as the handout computes it. On a grey
// material the two agree; on mixed_surfaces' red diffuse + teal mirror they do not, so the red
// channel comes out too dark and the blue too bright.
// A plausible student bug; the grader must fail it on mixed_surfaces and say why.
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

    // Probabilities proportional to each component's strength; stop on a near-black surface
    // (TODO lab3.3).
    const Material& m = hit.material;
    const float diffuse = reduceMax(m.Kd), mirror = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
    const float total = diffuse + mirror + transmit;
    if (total < 0.01f) return radiance;

    // Trace the chosen component and divide by its probability (TODO lab3.4). The bug: the
    // pick follows the luminances, the division the reduceMax strengths above.
    const float seenDiffuse = luminance(m.Kd), seenMirror = luminance(m.Ks);
    const float seenTotal = seenDiffuse + seenMirror + luminance(m.Kt);
    const float u = ctx.sampler.get1D() * seenTotal;
    if (u < seenDiffuse)
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                    (total / diffuse);
    else if (u < seenDiffuse + seenMirror)
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / mirror);
    else
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    return radiance;
}

} // namespace pathlab::importance
