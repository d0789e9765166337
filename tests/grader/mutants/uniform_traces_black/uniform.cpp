// Mutant 'uniform_traces_black': picks among all three components as lab 2 asks, but traces the
// picked component's ray even where that component is black: the same image (a black
// component's ray adds nothing), for 3.4 times the bounce rays on the VI2 box. A plausible
// student bug; the grader must fail its speed (see tests/grader/mutants.json), and the student
// release's own `make grade` must say its speed points are at risk. Lab 2: uniform selection of
// one component (handouts/02-uniform-pick.md).
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

    // Pick one of the three components, each with probability 1/3 (TODO lab2.3).
    constexpr float pickProbability = 1.0f / 3.0f;
    const int component = std::min(static_cast<int>(ctx.sampler.get1D() * 3.0f), 2);

    // Trace the chosen one and divide by its probability (TODO lab2.4), black or not: a black
    // component's ray adds 0 times what it finds, the same image, for a whole path of rays.
    const Material& m = hit.material;
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
