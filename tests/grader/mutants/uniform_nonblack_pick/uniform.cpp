// Mutant 'uniform_nonblack_pick': picks uniformly among the non-black components only (1/k each):
// unbiased and less noisy, not lab 2's pick among all three A plausible student bug; the grader
// must fail it (see tests/grader/mutants.json). Lab 2: uniform selection of one component
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

    // Pick uniformly among the components that are not black, and divide by 1/k: unbiased,
    // and quieter than the lab's pick among all three, but a bounce on every sample.
    const Material& m = hit.material;
    int components[3];
    int k = 0;
    if (!isBlack(m.Kd)) components[k++] = 0;
    if (!isBlack(m.Ks)) components[k++] = 1;
    if (!isBlack(m.Kt)) components[k++] = 2;
    if (k == 0) return radiance;
    const int component = components[std::min(static_cast<int>(ctx.sampler.get1D() * k), k - 1)];
    const float pickProbability = 1.0f / static_cast<float>(k);
    if (component == 0)
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) /
                    pickProbability;
    if (component == 1)
        radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) / pickProbability;
    if (component == 2)
        radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) / pickProbability;
    return radiance;
}

} // namespace pathlab::uniform
