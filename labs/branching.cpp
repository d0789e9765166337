// Lab 1: the branching path tracer. Handout: handouts/01-branching.md.
//
// Fill in the steps marked TODO(lab1.N), in order; each is explained in the handout section of
// the same name. Remove a step's PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

namespace pathlab::branching {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab1.1): also add it after a specular bounce, and never after a diffuse one.
    PATHLAB_TODO("lab1.1");
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);

    // TODO(lab1.2): the depth limit. From a hit at depth ctx.maxDepth, trace no further rays.
    PATHLAB_TODO("lab1.2", depth);

    const Material& m = hit.material;
    // TODO(lab1.3): the diffuse bounce. If Kd is not black, trace diffuseRay(hit, u) with
    // u = ctx.sampler.get2D() one level deeper and add what it brings back, weighted by Kd.
    PATHLAB_TODO("lab1.3", m);

    // TODO(lab1.4): the mirror bounce. If Ks is not black, trace mirrorRay(ray, hit), weight Ks.
    PATHLAB_TODO("lab1.4");

    // TODO(lab1.5): the refraction. If Kt is not black, trace refractionRay(ray, hit), weight Kt.
    PATHLAB_TODO("lab1.5");

    return radiance;
}

} // namespace pathlab::branching
