// Lab 2: uniform selection of one component. Handout: handouts/02-uniform-pick.md.
//
// Start from your lab 1. Fill in the steps marked TODO(lab2.N); each is explained in the
// handout section of the same name. Remove a step's PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

namespace pathlab::uniform {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab2.1): also add it after a specular bounce, and never after a diffuse one (lab 1.1).
    PATHLAB_TODO("lab2.1");
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);

    // TODO(lab2.2): the depth limit, as in lab 1.
    PATHLAB_TODO("lab2.2", depth);

    const Material& m = hit.material;
    // TODO(lab2.3): choose ONE of the three components (diffuse, mirror, refraction), each with
    // probability 1/3, from one number u = ctx.sampler.get1D().
    PATHLAB_TODO("lab2.3");

    // TODO(lab2.4): trace only the chosen component's ray (if that component is not black) and
    // divide what it brings back by the probability of having chosen it.
    PATHLAB_TODO("lab2.4", m);

    return radiance;
}

} // namespace pathlab::uniform
