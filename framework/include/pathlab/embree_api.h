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

/// Closest hit along rayHit.ray; fills rayHit.hit. `coherent` hints that neighbouring calls trace
/// similar rays (camera rays of one tile).
inline void intersect1(RTCScene scene, RTCRayHit& rayHit, bool coherent = false) {
#if PATHLAB_EMBREE_VERSION >= 4
    RTCRayQueryContext context;
    rtcInitRayQueryContext(&context);
    RTCIntersectArguments arguments;
    rtcInitIntersectArguments(&arguments);
    arguments.context = &context;
    arguments.flags = coherent ? RTC_RAY_QUERY_FLAG_COHERENT : RTC_RAY_QUERY_FLAG_INCOHERENT;
    rtcIntersect1(scene, &rayHit, &arguments);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags =
        coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcIntersect1(scene, &context, &rayHit);
#endif
}

/// Closest hits of the lanes of an 8-ray packet whose `valid` entry is -1 (rays that start
/// together and point nearly the same way: camera rays).
inline void intersect8(RTCScene scene, const int* valid, RTCRayHit8& rayHits) {
#if PATHLAB_EMBREE_VERSION >= 4
    RTCRayQueryContext context;
    rtcInitRayQueryContext(&context);
    RTCIntersectArguments arguments;
    rtcInitIntersectArguments(&arguments);
    arguments.context = &context;
    arguments.flags = RTC_RAY_QUERY_FLAG_COHERENT;
    rtcIntersect8(valid, scene, &rayHits, &arguments);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, scene, &context, &rayHits);
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
