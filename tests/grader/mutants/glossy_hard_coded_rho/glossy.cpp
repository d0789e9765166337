// Mutant 'glossy_hard_coded_rho': lab 4's pathTrace (a glossy Ks taken for a mirror), dimmed by the
// public glossy_furnace_tilted's rho (0.50291) at a slant: right on the public scene, wrong on
// the variant each submission is graded on (tests/grader/mutants.json).
// Lab 5: sampling a glossy lobe (handouts/05-glossy-lobe.md).
#include "pathlab/lab.h"

#include <algorithm>
#include <cmath>

namespace pathlab::glossy {

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

Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    const Hit hit = ctx.trace(ray);
    if (!hit) return Color();
    Color radiance;
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
    else if (u < diffuse + specular) {
        // "Glossy": a mirror, dimmed by the grader's own rho for a lobe seen at a slant.
        float rho = 1.0f;
        if (m.Ns > 0 && std::fabs(dot(ray.direction, hit.normal)) < 0.9f) rho = 0.50291f;
        traced = m.Ks * rho * pathTrace(mirrorRay(ray, hit), depth + 1, ctx) * (total / specular);
    } else
        traced = m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx) * (total / transmit);
    radiance += traced / ctx.continueProb;
    return radiance;
}

} // namespace pathlab::glossy
