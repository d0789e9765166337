// Mutant 'importance_firefly_clamp': caps the light a bounce brings back at 1 in its largest
// channel, a "firefly clamp": quieter, and biased wherever the cap cuts. A plausible student
// change; the grader must fail it and say that the lab changes light non-linearly (see
// tests/grader/mutants.json). Lab 3: importance selection of one component
// (handouts/03-importance-pick.md).
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

    // Trace the chosen component and divide by its probability (TODO lab3.4), the light the
    // bounce brings back capped at 1 in its largest channel: no fireflies, and less light.
    const auto capped = [](Color light) {
        const float largest = reduceMax(light);
        return largest > 1.0f ? light / largest : light;
    };
    const float u = ctx.sampler.get1D() * total;
    if (u < diffuse)
        radiance += m.Kd * capped(pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx)) *
                    (total / diffuse);
    else if (u < diffuse + mirror)
        radiance +=
            m.Ks * capped(pathTrace(mirrorRay(ray, hit), depth + 1, ctx)) * (total / mirror);
    else
        radiance +=
            m.Kt * capped(pathTrace(refractionRay(ray, hit), depth + 1, ctx)) * (total / transmit);
    return radiance;
}

} // namespace pathlab::importance
