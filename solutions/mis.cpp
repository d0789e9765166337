// Lab 6: multiple importance sampling (handouts/06-mis.md). Reference solution.
#include "pathlab/lab.h"

#include <algorithm>
#include <cmath>

namespace pathlab::mis {

// Lab 5's lobe and its density, as lab 5's solution has them (TODO lab6.1).
Vec3 sampleLobe(Vec2 u, float exponent) {
    const float cosAlpha = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));
    const float sinAlpha = std::sqrt(std::max(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float phi = 2.0f * Pi * u.y;
    return {sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha};
}

float lobePdf(Vec3 direction, float exponent) {
    if (direction.z <= 0) return 0.0f;
    return (exponent + 1.0f) / (2.0f * Pi) * std::pow(direction.z, exponent);
}

// The power heuristic with β = 2 (TODO lab6.2). A density of 0 gets no weight; both 0 cannot
// happen for a direction one of the two strategies drew.
float misWeight(float pdf, float otherPdf) {
    const float mine = pdf * pdf, other = otherPdf * otherPdf;
    return mine > 0 ? mine / (mine + other) : 0.0f;
}

namespace {

Color shade(const Ray& ray, const Hit& hit, int depth, PathContext& ctx);

// The light strategy at a glossy surface: a point on a light, through the glossy BRDF, weighted
// against the density with which the lobe would have drawn its direction (TODO lab6.3).
Color glossyLightSample(const Ray& ray, const Hit& hit, PathContext& ctx) {
    const Material& m = hit.material;
    const LightSample light = ctx.sampleLight(hit);
    if (isBlack(light.radiance) || !(light.pdf > 0)) return Color();
    const Vec3 d = lobeFrameDirection(ray, hit, light.direction);
    const float cosTheta = dot(light.direction, hit.normal);
    // A point or directional light: no bounce can find it, so this strategy takes all of it.
    const float weight =
        light.delta ? 1.0f
                    : ctx.strategyWeight(Strategy::Light, misWeight(light.pdf, lobePdf(d, m.Ns)));
    return phongBrdf(m, d.z) * light.radiance * (cosTheta * weight / light.pdf);
}

// The lobe strategy: lab 5's glossy bounce, whose ray's first hit is traced here, so that the
// light it finds straight away is weighted against the light's density for it (TODO lab6.4).
Color glossyBounce(const Ray& ray, const Hit& hit, int depth, PathContext& ctx) {
    const Material& m = hit.material;
    const Vec3 d = sampleLobe(ctx.sampler.get2D(), m.Ns);
    const float pdf = lobePdf(d, m.Ns);
    const Ray bounce = glossyRay(ray, hit, d);
    const float cosTheta = dot(bounce.direction, hit.normal);
    if (cosTheta <= 0 || pdf <= 0) return Color();
    const Hit next = ctx.trace(bounce);
    if (!next) return Color();
    const float weight =
        ctx.strategyWeight(Strategy::Lobe, misWeight(pdf, ctx.lightPdf(hit, next)));
    return phongBrdf(m, d.z) * cosTheta / pdf *
           (next.emitted * weight + shade(bounce, next, depth + 1, ctx));
}

// Lab 5's path from a found surface, with both strategies at a glossy one (TODO lab6.5).
Color shade(const Ray& ray, const Hit& hit, int depth, PathContext& ctx) {
    Color radiance;
    // Emission that neither strategy counted: a diffuse bounce's light came by next-event
    // estimation, a glossy bounce's was weighted where the bounce left.
    if (ray.kind == RayKind::Camera || ray.kind == RayKind::Specular) radiance += hit.emitted;
    radiance += ctx.directLight(hit);

    const Material& m = hit.material;
    const bool glossy = m.Ns > 0;
    if (glossy && !isBlack(m.Ks)) radiance += glossyLightSample(ray, hit, ctx);

    if (ctx.sampler.get1D() >= ctx.continueProb) return radiance;

    const float diffuse = reduceMax(m.Kd), specular = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
    const float total = diffuse + specular + transmit;
    if (total < 0.01f) return radiance;

    const float u = ctx.sampler.get1D() * total;
    Color traced;
    if (u < diffuse)
        traced = m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                 (total / diffuse);
    else if (u < diffuse + specular && glossy)
        traced = glossyBounce(ray, hit, depth, ctx) * (total / specular);
    else if (u < diffuse + specular)
        traced = m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / specular);
    else
        traced = m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    radiance += traced / ctx.continueProb;
    return radiance;
}

} // namespace

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    return shade(ray, hit, depth, ctx);
}

} // namespace pathlab::mis
