// Lab 5: sampling a glossy lobe. Handout: handouts/05-glossy-lobe.md.
//
// Here you write a sampling routine and its density yourself, and prove them right with the warp
// test (`make warptest LAB=glossy`) before the path tracer uses them. Fill in the steps marked
// TODO(lab5.N); each is explained in the handout section of the same name. Remove a step's
// PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

#include <cmath>

namespace pathlab::glossy {

// TODO(lab5.1): a direction from the Phong lobe about z, with density proportional to cosⁿ α
// (n = exponent, α the angle to z): cos α by inverting the CDF of α's density, φ uniform in
// [0, 2π). u holds two numbers uniform in [0, 1). Return a unit vector with z = cos α.
Vec3 sampleLobe(Vec2 u, float exponent) {
    PATHLAB_TODO("lab5.1", u, exponent);
    return {0, 0, 1};
}

// TODO(lab5.2): the density of sampleLobe's directions, per unit solid angle: cosⁿ α times the
// constant that makes it integrate to 1 over the hemisphere (and 0 below it).
float lobePdf(Vec3 direction, float exponent) {
    PATHLAB_TODO("lab5.2", direction, exponent);
    return 1.0f;
}

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab5.3): continue the path as your lab 4 does: emission where next-event estimation
    // could not have counted it, Russian roulette, one component picked by importance.
    PATHLAB_TODO("lab5.3", depth);
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);

    // TODO(lab5.4): where lab 4 took the mirror ray, a glossy material (hit.material.Ns > 0)
    // bounces in a direction d = sampleLobe(ctx.sampler.get2D(), Ns) instead: the ray is
    // glossyRay(ray, hit, d), and what it brings back is weighted by
    // phongBrdf(m, d.z) * cos θ / lobePdf(d, Ns), θ its angle to hit.normal (nothing below the
    // surface), and divided by the pick's and roulette's probabilities as before.
    PATHLAB_TODO("lab5.4");

    return radiance;
}

} // namespace pathlab::glossy
