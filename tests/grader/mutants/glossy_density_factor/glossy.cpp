// Mutant 'glossy_density_factor': lobePdf's normalisation is (n + 1)/π, twice the right one
// A plausible student bug; the lab tests must fail it (tests/estimators/CMakeLists.txt).
// Lab 5: sampling a glossy lobe (handouts/05-glossy-lobe.md).
#include "pathlab/lab.h"

#include <algorithm>
#include <cmath>

namespace pathlab::glossy {

// The Phong lobe cosⁿ α about z, normalised: p(ω) = (n + 1) / (2π) · cosⁿ α. Its marginal in
// α has the CDF 1 − cosⁿ⁺¹ α, inverted with 1 − u (as uniform as u); φ is uniform (TODO lab5.1).
Vec3 sampleLobe(Vec2 u, float exponent) {
    const float cosAlpha = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));
    const float sinAlpha = std::sqrt(std::max(0.0f, 1.0f - cosAlpha * cosAlpha));
    const float phi = 2.0f * Pi * u.y;
    return {sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha};
}

// Its density per unit solid angle (TODO lab5.2).
float lobePdf(Vec3 direction, float exponent) {
    if (direction.z <= 0) return 0.0f;
    return (exponent + 1.0f) / Pi * std::pow(direction.z, exponent);
}

namespace {

// The glossy bounce: one direction from the lobe about the mirror direction, weighted by
// f · cos θ / p (TODO lab5.4). A direction below the surface carries nothing.
Color glossyBounce(const Ray& ray, const Hit& hit, int depth, PathContext& ctx) {
    const Material& m = hit.material;
    const Vec3 d = sampleLobe(ctx.sampler.get2D(), m.Ns);
    const float pdf = lobePdf(d, m.Ns);
    const Ray bounce = glossyRay(ray, hit, d);
    const float cosTheta = dot(bounce.direction, hit.normal);
    if (cosTheta <= 0 || pdf <= 0) return Color();
    // f·cos θ first, then / p: a density that underflows (a wrong sampler far out in the lobe)
    // must not overflow cos θ / p.
    return phongBrdf(m, d.z) * cosTheta / pdf * pathTrace(bounce, depth + 1, ctx);
}

} // namespace

// Lab 4's path, with the glossy bounce where a material's Ks is a lobe (TODO lab5.3).
Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;

    // Emission where next-event estimation could not have counted it: after a glossy bounce too.
    if (ray.kind != RayKind::Diffuse) radiance += hit.emitted;
    radiance += ctx.directLight(hit);

    if (ctx.sampler.get1D() >= ctx.continueProb) return radiance;

    const Material& m = hit.material;
    const float diffuse = reduceMax(m.Kd), specular = reduceMax(m.Ks), transmit = reduceMax(m.Kt);
    const float total = diffuse + specular + transmit;
    if (total < 0.01f) return radiance;

    const float u = ctx.sampler.get1D() * total;
    Color traced;
    if (u < diffuse)
        traced = m.Kd * pathTrace(diffuseRay(hit, ctx.sampler.get2D()), depth + 1, ctx) *
                 (total / diffuse);
    else if (u < diffuse + specular && m.Ns > 0)
        traced = glossyBounce(ray, hit, depth, ctx) * (total / specular);
    else if (u < diffuse + specular)
        traced = m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / specular);
    else
        traced = m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    radiance += traced / ctx.continueProb;
    return radiance;
}

} // namespace pathlab::glossy
