// Hostile submission: lab 1, the reference solution's, with code that only ThreadSanitizer's build
// compiles: a call of a function that exists nowhere, so that build of the lab does not load and
// the race check cannot run it (a racy lab would keep its points). The grader holds a lab that
// differs under the sanitizer against it, as a race.
#include "pathlab/lab.h"

#if defined(__SANITIZE_THREAD__)
extern "C" int pathlab_no_such_symbol();
[[maybe_unused]] static const int hiddenFromTsan = pathlab_no_such_symbol();
#endif

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission, where next-event estimation could not have counted it (TODO lab1.1).
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;

    // Direct light at diffuse surfaces: next-event estimation.
    radiance += ctx.directLight(hit);

    // The depth limit: no bounce rays from a hit at maxDepth (TODO lab1.2).
    if (depth >= ctx.maxDepth) return radiance;

    // Every non-zero component, each with its own ray (TODOs lab1.3-lab1.5).
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
