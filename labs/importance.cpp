// Lab 3: importance selection of one component. Handout: handouts/03-importance-pick.md.
//
// Start from your lab 2. Fill in the steps marked TODO(lab3.N); each is explained in the
// handout section of the same name. Remove a step's PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

namespace pathlab::importance {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab3.1): also add it after a specular bounce, and never after a diffuse one (lab 1.1).
    PATHLAB_TODO("lab3.1");
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);

    // TODO(lab3.2): the depth limit, as in lab 1.
    PATHLAB_TODO("lab3.2", depth);

    const Material& m = hit.material;
    // TODO(lab3.3): give each component a probability proportional to its strength,
    // reduceMax(Kd), reduceMax(Ks), reduceMax(Kt), normalised by their sum; if the sum is below
    // 0.01 the surface is all but black: stop here.
    PATHLAB_TODO("lab3.3", m);

    // TODO(lab3.4): choose one component with those probabilities (u = ctx.sampler.get1D()),
    // trace its ray and divide what it brings back by its probability.
    PATHLAB_TODO("lab3.4");

    return radiance;
}

} // namespace pathlab::importance
