#pragma once
/// Where a ray that leaves a surface starts: every bounce (scattering.cpp) and shadow ray
/// (PathContext::directLight) begins here, and none needs the Embree scene to know it.

#include "pathlab/hit.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// A point just off the surface at `hit`, on the side `direction` leaves by, so a ray started
/// there does not find the surface it left again. Inline: every bounce and shadow ray starts
/// here.
inline Vec3 offsetRayOrigin(const Hit& hit, const Vec3& direction) {
    // Float positions carry a relative error near 1e-7; a step of a few hundred ulps along the
    // geometric normal clears it at any scene scale.
    const float epsilon = 2e-5f * (1.0f + maxAbsComponent(hit.position));
    const float side = dot(direction, hit.geometricNormal) >= 0 ? 1.0f : -1.0f;
    return hit.position + hit.geometricNormal * (side * epsilon);
}

} // namespace pathlab
