#pragma once
/// The one place that knows whether this is Embree 3 (Debian 12) or Embree 4 (Ubuntu 24.04,
/// Homebrew). Everything else calls these wrappers.

#if __has_include(<embree4/rtcore.h>)
#include <embree4/rtcore.h>
#define PATHLAB_EMBREE_VERSION 4
#else
#include <embree3/rtcore.h>
#define PATHLAB_EMBREE_VERSION 3
#endif

namespace pathlab::embree {

/// What a closest-hit query passes to Embree besides the rays: Embree 4's query arguments, or
/// Embree 3's intersect context. `coherent` hints that neighbouring calls trace similar rays
/// (camera rays of one tile).
struct ClosestHitQuery {
#if PATHLAB_EMBREE_VERSION >= 4
    RTCRayQueryContext context;
    RTCIntersectArguments arguments;
    explicit ClosestHitQuery(bool coherent) {
        rtcInitRayQueryContext(&context);
        rtcInitIntersectArguments(&arguments);
        arguments.context = &context;
        arguments.flags = coherent ? RTC_RAY_QUERY_FLAG_COHERENT : RTC_RAY_QUERY_FLAG_INCOHERENT;
    }
    ClosestHitQuery(const ClosestHitQuery&) = delete; // arguments points into itself
#else
    RTCIntersectContext context;
    explicit ClosestHitQuery(bool coherent) {
        rtcInitIntersectContext(&context);
        context.flags =
            coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    }
#endif
};

/// Closest hit along rayHit.ray; fills rayHit.hit.
inline void intersect1(RTCScene scene, RTCRayHit& rayHit, bool coherent = false) {
    ClosestHitQuery query(coherent);
#if PATHLAB_EMBREE_VERSION >= 4
    rtcIntersect1(scene, &rayHit, &query.arguments);
#else
    rtcIntersect1(scene, &query.context, &rayHit);
#endif
}

/// Closest hits of the lanes of an 8-ray packet whose `valid` entry is -1 (rays that start
/// together and point nearly the same way: camera rays).
inline void intersect8(RTCScene scene, const int* valid, RTCRayHit8& rayHits) {
    ClosestHitQuery query(true);
#if PATHLAB_EMBREE_VERSION >= 4
    rtcIntersect8(valid, scene, &rayHits, &query.arguments);
#else
    rtcIntersect8(valid, scene, &query.context, &rayHits);
#endif
}

/// Whether anything blocks `ray` between tnear and tfar; Embree sets ray.tfar to -inf if so.
inline bool occluded1(RTCScene scene, RTCRay& ray) {
#if PATHLAB_EMBREE_VERSION >= 4
    RTCOccludedArguments arguments;
    rtcInitOccludedArguments(&arguments);
    rtcOccluded1(scene, &ray, &arguments);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, &ray);
#endif
    return ray.tfar < 0.0f;
}

} // namespace pathlab::embree
