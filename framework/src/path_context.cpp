#include "pathlab/path_context.h"

#include "pathlab/constants.h"
#include "pathlab/render_scene.h"
#include "pathlab/triangle_sampling.h"

#include <utility>

namespace pathlab {

Hit PathContext::trace(const Ray& ray) {
    ++counters_.intersect;
    if (log_) log_->closestHit.push_back(ray);
    if (packet_) {
        // Only the first trace() after priming may be the packet's camera ray.
        const CameraPacket* packet = std::exchange(packet_, nullptr);
        if (packet->holds(lane_, ray)) return scene_.hit(*packet, lane_);
    }
    return scene_.intersect(ray);
}

Color PathContext::directLight(const Hit& hit) {
    const LightSampler& lights = scene_.lights();
    if (!hit || isBlack(hit.material.Kd) || lights.empty()) return Color();

    float pickProbability = 0;
    const float u = sampler.get1D();
    const float v = sampler.get1D();
    const LightSource& light = lights.pick(u, v, pickProbability);

    // Radiance arriving from the light along the shadow ray, divided by the pdf of the chosen
    // point in solid angle at the receiver, i.e. L·cosθ'/(r²·p_area) for an area light.
    const Vec3 lightPosition = light.type == LightSource::Type::Point
                                   ? light.position
                                   : sampleTriangleUniform(light.a, light.b, light.c,
                                                           sampler.get2D());
    const Vec3 toLight = lightPosition - hit.position;
    const float distance2 = dot(toLight, toLight);
    // Both sides' cosines before any square root: light from behind the receiver, or from the
    // back of an area light, is black.
    const float cosReceiver = dot(hit.normal, toLight);
    if (cosReceiver <= 0) return Color();
    Color arriving; // incident radiance × (geometry term) / pdf, before the receiver's cosine
    if (light.type == LightSource::Type::Point) {
        arriving = light.intensity / distance2;
    } else {
        // Only the front side emits; cosθ'·area = dot(-toLight/r, areaNormal/2).
        const float frontTimesHalf = -dot(toLight, light.areaNormal) * 0.5f;
        if (frontTimesHalf < 0) return Color();
        const float cosTimesArea = frontTimesHalf / std::sqrt(distance2);
        if (cosTimesArea <= 0) return Color();
        arriving = light.Ke * (cosTimesArea / distance2);
    }

    ++counters_.occluded;
    const Vec3 origin = offsetRayOrigin(hit, toLight);
    if (log_) log_->occlusion.push_back({origin, lightPosition});
    if (scene_.occluded(origin, lightPosition)) return Color();
    return hit.material.Kd * arriving *
           (InvPi * cosReceiver / std::sqrt(distance2) / pickProbability);
}

} // namespace pathlab
