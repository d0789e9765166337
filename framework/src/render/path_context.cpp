#include "pathlab/path_context.h"

#include "pathlab/render/camera_packet.h"
#include "pathlab/support/check.h"
#include "pathlab/constants.h"
#include "pathlab/render/lab_parameters.h"
#include "pathlab/render/path_driver.h"
#include "pathlab/render/path_recorder.h"
#include "pathlab/render/ray_log.h"
#include "pathlab/render/ray_origin.h"
#include "pathlab/render/render_scene.h"
#include "pathlab/render/triangle_sampling.h"

#include <cmath>
#include <string>
#include <utility>

namespace pathlab {

namespace {

const char* rayKindName(RayKind kind) {
    switch (kind) {
    case RayKind::Camera: return "camera";
    case RayKind::Diffuse: return "diffuse";
    case RayKind::Specular: return "specular";
    case RayKind::Glossy: return "glossy";
    }
    return "unknown";
}

} // namespace

PathContext::PathContext(const RenderScene& scene, const LabParameters& parameters)
    : sampler(PathDriver::samplerFor(0, 0, 0)), maxDepth(parameters.maxDepth),
      continueProb(parameters.continueProb), scene_(scene), strategies_(parameters.strategies) {}

Hit PathContext::traceUnrecorded(const Ray& ray, CallSite caller) {
    // A ray built by a lab: Embree would trace a non-unit direction, with every distance and
    // offset along it scaled, and a NaN one would find nothing. Both come from a step before.
    // The check names the line of this trace() call, but the ray was usually made further up:
    // where pathTrace was called with it. The message says so, with the ray's kind to find it
    // by. (The message is made only when the check fails.)
    const float length2 = dot(ray.direction, ray.direction);
    PATHLAB_CHECK_CALLER(std::abs(length2 - 1.0f) < 1e-3f, caller,
                         "ctx.trace(ray) needs a unit-length ray.direction, and this " +
                             std::string(rayKindName(ray.kind)) + " ray's has length " +
                             std::to_string(std::sqrt(length2)) +
                             ": where this ray was made (for a bounce, before the call of "
                             "pathTrace that received it), " +
                             (std::isfinite(length2)
                                  ? "normalize() its direction"
                                  : "look for a division by zero that made it NaN"));
    ++closestHitRays_;
    if (log_) log_->closestHit.push_back(ray);
    if (packet_) {
        // Only the first trace() after priming may be the packet's camera ray.
        const CameraPacket* packet = std::exchange(packet_, nullptr);
        if (packet->holds(lane_, ray)) return scene_.hit(*packet, lane_);
    }
    return scene_.intersect(ray);
}

Color PathContext::directLightUnrecorded(const Hit& hit, CallSite caller) {
    PATHLAB_CHECK_CALLER(hit.found, caller,
                         "ctx.directLight(hit) needs a surface: call it after `if (!hit)` has "
                         "returned for a ray that left the scene");
    const LightSampler& lights = scene_.lights();
    if (isBlack(hit.material.Kd) || lights.empty()) return Color();

    float pickProbability = 0;
    const float u = sampler.get1D();
    const float v = sampler.get1D();
    const LightSource& light = lights.pick(u, v, pickProbability);
    PATHLAB_DCHECK(pickProbability > 0);
    if (light.type == LightSource::Type::Directional) return directionalLight(hit, light);

    // Radiance arriving from the light along the shadow ray, divided by the pdf of the chosen
    // point in solid angle at the receiver, i.e. L·cosθ'/(r²·p_area) for an area light.
    const Vec3 lightPosition =
        light.type == LightSource::Type::Point
            ? light.position
            : sampleTriangleUniform(light.a, light.b, light.c, sampler.get2D());
    const Vec3 toLight = lightPosition - hit.position;
    const float distance2 = dot(toLight, toLight);
    // Both sides' cosines before any square root: light from behind the receiver, or from the
    // back of an area light, is black.
    const float cosReceiver = dot(hit.normal, toLight);
    if (cosReceiver <= 0) return Color();
    // One division for the distances, then products.
    const float inverseDistance = 1.0f / std::sqrt(distance2);
    const float inverseDistance2 = inverseDistance * inverseDistance;
    Color arriving; // incident radiance × (geometry term) / pdf, before the receiver's cosine
    if (light.type == LightSource::Type::Point) {
        arriving = light.intensity * inverseDistance2;
    } else {
        // Only the front side emits; cosθ'·area = dot(-toLight/r, areaNormal/2).
        const float frontTimesHalf = -dot(toLight, light.areaNormal) * 0.5f;
        if (frontTimesHalf < 0) return Color();
        const float cosTimesArea = frontTimesHalf * inverseDistance;
        if (cosTimesArea <= 0) return Color();
        arriving = light.Ke * (cosTimesArea * inverseDistance2);
    }

    ++shadowRays_;
    const Vec3 origin = offsetRayOrigin(hit, toLight);
    if (log_) log_->occlusion.push_back({origin, lightPosition});
    if (scene_.occluded(origin, lightPosition)) return Color();
    return hit.material.Kd * arriving * (InvPi * cosReceiver * inverseDistance * light.inversePmf);
}

// Out of directLightUnrecorded, which stays as it was for point and triangle lights: a scene
// without directional lights pays one comparison per call for them.
Color PathContext::directionalLight(const Hit& hit, const LightSource& light) {
    const float cosReceiver = dot(hit.normal, light.towardLight);
    if (cosReceiver <= 0) return Color();
    ++shadowRays_;
    const Vec3 origin = offsetRayOrigin(hit, light.towardLight);
    const Vec3 beyondScene = origin + light.towardLight * light.shadowDistance;
    if (log_) log_->occlusion.push_back({origin, beyondScene});
    if (scene_.occluded(origin, beyondScene)) return Color();
    // Irradiance E·cosθ on the receiver, reflected by Kd/π.
    return hit.material.Kd * light.irradiance * (InvPi * cosReceiver * light.inversePmf);
}

// The recorded versions run the usual code, then hand the recorder what happened; it may replace
// what the lab receives, to probe how the lab weights it (pathlab/render/path_recorder.h).
Hit PathContext::recordedTrace(const Ray& ray, CallSite caller) {
    const Hit hit = traceUnrecorded(ray, caller);
    return recorder_->traced(ray, hit, sampler);
}

Color PathContext::recordedDirectLight(const Hit& hit, CallSite caller) {
    RayLog* renderLog = std::exchange(log_, &recorder_->shadowRays());
    const Sampler before = sampler;
    const size_t shadowRaysBefore = log_->occlusion.size();
    const Color light = directLightUnrecorded(hit, caller);
    const bool sentShadowRay = log_->occlusion.size() > shadowRaysBefore;
    if (renderLog && sentShadowRay) renderLog->occlusion.push_back(log_->occlusion.back());
    log_ = renderLog;
    return recorder_->directLit(hit, light, sentShadowRay, before, sampler);
}

} // namespace pathlab
