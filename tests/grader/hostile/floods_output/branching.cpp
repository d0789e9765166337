// Hostile submission: lab 1 done right, printing a line for every camera ray (about 40 MB per
// correctness render), which the grader would read to the end. It reads a render's first 4 MiB,
// then closes the pipe (the viewer ignores SIGPIPE: the lab's prints fail, the render goes on),
// and says so in the feedback.
#include "pathlab/lab.h"

#include <cstdio>

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    if (depth == 0)
        std::printf("camera ray from (%g, %g, %g) towards (%g, %g, %g), and some padding\n",
                    ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                    ray.direction.z);
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);
    if (depth >= ctx.maxDepth) return radiance;
    const Material& m = hit.material;
    if (!isBlack(m.Kd))
        radiance += m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx);
    if (!isBlack(m.Ks)) radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    if (!isBlack(m.Kt)) radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    return radiance;
}

} // namespace pathlab::branching
