#pragma once
/// How PathLab's rays become Embree's queries. RenderScene traces these, and the benchmark replays
/// the very same queries to time Embree's traversal alone.

#include "pathlab/render/camera_packet.h"
#include "pathlab/render/embree_api.h"
#include "pathlab/ray.h"
#include "pathlab/vec3.h"

#include <limits>

namespace pathlab::embree {

/// The closest-hit query for `ray`: the whole half-line t in [0, inf).
inline RTCRayHit closestHitQuery(const Ray& ray) {
    RTCRayHit rayHit;
    rayHit.ray.org_x = ray.origin.x;
    rayHit.ray.org_y = ray.origin.y;
    rayHit.ray.org_z = ray.origin.z;
    rayHit.ray.dir_x = ray.direction.x;
    rayHit.ray.dir_y = ray.direction.y;
    rayHit.ray.dir_z = ray.direction.z;
    rayHit.ray.tnear = 0.0f;
    rayHit.ray.tfar = std::numeric_limits<float>::infinity();
    rayHit.ray.time = 0.0f;
    rayHit.ray.mask = 0xFFFFFFFFu;
    rayHit.ray.id = 0;
    rayHit.ray.flags = 0;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayHit;
}

/// The closest-hit query for the rays of `packet`, lane by lane as closestHitQuery.
inline RTCRayHit8 cameraPacketQuery(const CameraPacket& packet) {
    RTCRayHit8 rayHits;
    for (int i = 0; i < CameraPacket::Size; ++i) {
        const Ray& ray = packet.rays[i < packet.count ? i : 0];
        rayHits.ray.org_x[i] = ray.origin.x;
        rayHits.ray.org_y[i] = ray.origin.y;
        rayHits.ray.org_z[i] = ray.origin.z;
        rayHits.ray.dir_x[i] = ray.direction.x;
        rayHits.ray.dir_y[i] = ray.direction.y;
        rayHits.ray.dir_z[i] = ray.direction.z;
        rayHits.ray.tnear[i] = 0.0f;
        rayHits.ray.tfar[i] = std::numeric_limits<float>::infinity();
        rayHits.ray.time[i] = 0.0f;
        rayHits.ray.mask[i] = 0xFFFFFFFFu;
        rayHits.ray.id[i] = 0;
        rayHits.ray.flags[i] = 0;
        rayHits.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rayHits.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    return rayHits;
}

/// The occlusion query for the segment from `from` to `to`, both ends excluded.
inline RTCRay occlusionQuery(const Vec3& from, const Vec3& to) {
    const Vec3 d = to - from;
    // Stop just short of the light's own surface (the direction is not normalised: t = 1 is it).
    const float tfar = 1.0f - 1e-4f;
    // In RTCRay's order (Embree 3 and 4 alike): origin, tnear, direction, time, tfar, mask, id,
    // flags.
    return RTCRay{from.x, from.y, from.z, 0.0f, d.x, d.y, d.z, 0.0f, tfar, 0xFFFFFFFFu, 0, 0};
}

} // namespace pathlab::embree
