// Lab 6's light sampling: PathContext::sampleLight, lightPdf and strategyWeight, the densities
// in solid angle that multiple importance sampling weighs (handout 06).
#include "pathlab/path_context.h"

#include "pathlab/render/path_recorder.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/render/ray_origin.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/triangle_sampling.h"
#include "pathlab/support/check.h"

#include <cmath>
#include <string>
#include <utility>

namespace pathlab {

LightSample PathContext::sampleLight(const Hit& hit, CallSite caller) {
    if (!recorder_) return sampleLightUnrecorded(hit, caller);
    // The inspector draws the shadow ray with the path's, as it does directLight()'s.
    RayLog* renderLog = std::exchange(log_, &recorder_->shadowRays());
    const Sampler before = sampler;
    const size_t shadowRaysBefore = log_->occlusion.size();
    const LightSample sample = sampleLightUnrecorded(hit, caller);
    if (renderLog && log_->occlusion.size() > shadowRaysBefore)
        renderLog->occlusion.push_back(log_->occlusion.back());
    log_ = renderLog;
    recorder_->sampledLight(before, sampler);
    return sample;
}

LightSample PathContext::sampleLightUnrecorded(const Hit& hit, CallSite caller) {
    PATHLAB_CHECK_CALLER(hit.found, caller,
                         "ctx.sampleLight(hit) needs a surface: call it after `if (!hit)` has "
                         "returned for a ray that left the scene");
    LightSample sample;
    const LightSampler& lights = scene_.lights();
    if (lights.empty()) return sample;

    float pickProbability = 0;
    const float u = sampler.get1D();
    const float v = sampler.get1D();
    const LightSource& light = lights.pick(u, v, pickProbability);
    Vec3 target; // where the shadow ray ends
    Color arriving;
    if (light.type == LightSource::Type::Directional) {
        sample.direction = light.towardLight;
        sample.distance = light.shadowDistance;
        sample.delta = true;
        sample.pdf = pickProbability;
        arriving = light.irradiance;
        target = offsetRayOrigin(hit, light.towardLight) + light.towardLight * light.shadowDistance;
    } else {
        target = light.type == LightSource::Type::Point
                     ? light.position
                     : sampleTriangleUniform(light.a, light.b, light.c, sampler.get2D());
        const Vec3 toLight = target - hit.position;
        const float distance2 = dot(toLight, toLight);
        sample.distance = std::sqrt(distance2);
        sample.direction = toLight / sample.distance;
        if (light.type == LightSource::Type::Point) {
            sample.delta = true;
            sample.pdf = pickProbability;
            arriving = light.intensity / distance2;
        } else {
            // Only the front emits: from the back, neither radiance nor a density.
            const float twiceArea = length(light.areaNormal);
            sample.cosAtLight = -dot(sample.direction, light.areaNormal) / twiceArea;
            if (!(sample.cosAtLight > 0)) return sample;
            // pick / area per unit area, times r² / cos θ' per unit solid angle.
            sample.pdf = lights.trianglePointDensity(light.Ke) * distance2 / sample.cosAtLight;
            arriving = light.Ke;
        }
    }
    if (!(sample.pdf > 0) || !std::isfinite(sample.pdf)) {
        sample.pdf = 0;
        return sample;
    }
    if (dot(hit.normal, sample.direction) <= 0) return sample; // below the surface: black

    ++shadowRays_;
    const Vec3 origin = offsetRayOrigin(hit, sample.direction);
    if (log_) log_->occlusion.push_back({origin, target});
    if (!scene_.occluded(origin, target)) sample.radiance = arriving;
    return sample;
}

float PathContext::lightPdf(const Hit& hit, const Hit& onLight, CallSite caller) const {
    PATHLAB_CHECK_CALLER(hit.found, caller,
                         "ctx.lightPdf(hit, onLight) needs `hit`, the surface the ray left, to "
                         "be a found surface");
    if (!onLight.found || isBlack(onLight.emitted)) return 0.0f;
    const Vec3 toLight = onLight.position - hit.position;
    const float distance2 = dot(toLight, toLight);
    const float cosAtLight =
        std::fabs(dot(toLight, onLight.geometricNormal)) / std::sqrt(distance2);
    if (!(cosAtLight > 0)) return 0.0f;
    const float pdf =
        scene_.lights().trianglePointDensity(onLight.material.Ke) * distance2 / cosAtLight;
    return std::isfinite(pdf) ? pdf : 0.0f;
}

float PathContext::strategyWeight(Strategy strategy, float misWeight, CallSite caller) const {
    // A little past 1 for the float rounding of p²/(p² + q²).
    PATHLAB_CHECK_CALLER(misWeight >= 0.0f && misWeight <= 1.0f + 1e-5f, caller,
                         "ctx.strategyWeight's weight " + std::to_string(misWeight) +
                             " is not between 0 and 1: misWeight (TODO lab6.2) must return a "
                             "weight, from two densities that are numbers of 0 or more");
    switch (strategies_) {
    case StrategyChoice::Both: return misWeight;
    case StrategyChoice::LightOnly: return strategy == Strategy::Light ? 1.0f : 0.0f;
    case StrategyChoice::LobeOnly: return strategy == Strategy::Lobe ? 1.0f : 0.0f;
    }
    return misWeight;
}

} // namespace pathlab
