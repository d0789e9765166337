// Lab 6: multiple importance sampling. Handout: handouts/06-mis.md.
//
// At a glossy surface, light can be found two ways: by sampling a point on a light (next-event
// estimation) or by sampling the lobe (lab 5's bounce). Here you use both, each weighted so
// that the two weights add up to one for every direction, and the better strategy for that
// direction gets most of it. Fill in the steps marked TODO(lab6.N); each is explained in the
// handout section of the same name. Remove a step's PATHLAB_TODO line when you have written it.
#include "pathlab/lab.h"

#include <cmath>

namespace pathlab::mis {

// TODO(lab6.1): your lab 5 sampleLobe and lobePdf, copied here as they are (each lab is built
// on its own; `make warptest LAB=mis` checks them again).
Vec3 sampleLobe(Vec2 u, float exponent) {
    PATHLAB_TODO("lab6.1", u, exponent);
    return {0, 0, 1};
}

// (lab6.1, its second half: sampleLobe's marker above warns for both.)
float lobePdf(Vec3 direction, float exponent) {
    (void)direction;
    (void)exponent;
    return 1.0f;
}

// TODO(lab6.2): the power heuristic's weight (β = 2) for a strategy that drew a direction with
// density `pdf`, where the other strategy would have drawn it with density `otherPdf`. (Until
// then every direction is weighted one half by each strategy: also one in all, but noisier.)
float misWeight(float pdf, float otherPdf) {
    PATHLAB_TODO("lab6.2", pdf, otherPdf);
    return 0.5f;
}

Color shade(const Ray& ray, const Hit& hit, int depth, PathContext& ctx);

// TODO(lab6.3): the light strategy at a glossy surface. Take light = ctx.sampleLight(hit) and
// d = lobeFrameDirection(ray, hit, light.direction); return
// phongBrdf(m, d.z) · light.radiance · cos θ / light.pdf, weighted by
// ctx.strategyWeight(Strategy::Light, misWeight(light.pdf, lobePdf(d, m.Ns))), or by 1 for a
// light.delta (nothing when light.radiance is black).
Color glossyLightSample(const Ray& ray, const Hit& hit, PathContext& ctx) {
    PATHLAB_TODO("lab6.3", ray, hit, ctx);
    return Color();
}

// TODO(lab6.4): the lobe strategy: lab 5's glossy bounce, but trace its ray here,
// next = ctx.trace(bounce) (black if it found nothing: shade needs a surface), and return
// f · cos θ / p times (next.emitted · its weight + shade(bounce, next, depth + 1, ctx)), the
// weight ctx.strategyWeight(Strategy::Lobe, misWeight(p, ctx.lightPdf(hit, next))).
Color glossyBounce(const Ray& ray, const Hit& hit, int depth, PathContext& ctx) {
    PATHLAB_TODO("lab6.4", ray, hit, depth, ctx);
    return Color();
}

// The path from a surface a ray found.
Color shade(const Ray& ray, const Hit& hit, int depth, PathContext& ctx) {
    Color radiance;

    // Emission. Given: what a camera ray sees of a light.
    // TODO(lab6.5): your lab 5 path from here on, with three changes: emission is added only
    // where no strategy counted it (a camera or specular ray), a glossy material adds
    // glossyLightSample(ray, hit, ctx) beside ctx.directLight(hit), and where lab 5 bounced off
    // the glossy lobe this lab calls glossyBounce(ray, hit, depth, ctx).
    PATHLAB_TODO("lab6.5", depth);
    if (ray.kind == RayKind::Camera) radiance += hit.emitted;

    // Direct light at diffuse surfaces (next-event estimation). Given.
    radiance += ctx.directLight(hit);
    return radiance;
}

// Given: the first hit, then the path from it.
Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color(); // the ray left the scene
    return shade(ray, hit, depth, ctx);
}

} // namespace pathlab::mis
