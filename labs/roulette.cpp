// Lab 4: Russian roulette instead of a depth limit. Handout: handouts/04-russian-roulette.md.
//
// Start from your lab 3. Fill in the steps marked TODO(lab4.N); each is explained in the
// handout section of the same name. Remove a step's PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

namespace pathlab::roulette {

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab4.1): also add it after a specular bounce, and never after a diffuse one (lab 1.1).
    PATHLAB_TODO("lab4.1");
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);

    // TODO(lab4.2): no depth limit this time. Instead, continue the path only with probability
    // ctx.continueProb (one number from ctx.sampler.get1D()); otherwise stop here.
    PATHLAB_TODO("lab4.2");

    const Material& m = hit.material;
    // TODO(lab4.3): choose one component by importance, as in lab 3, and trace its ray.
    PATHLAB_TODO("lab4.3", depth, m);

    // TODO(lab4.4): divide what the traced ray brings back by the probability of the choice AND
    // by the probability of having continued at all.
    PATHLAB_TODO("lab4.4");

    return radiance;
}

} // namespace pathlab::roulette
