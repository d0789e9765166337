#pragma once
/// What a traced ray found.

#include "pathlab/color.h"
#include "pathlab/material.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// The closest surface along a ray. `found` is false (and nothing else is meaningful) when
/// the ray leaves the scene.
struct Hit {
    bool found = false;
    Vec3 position;          ///< world-space point on the surface
    Vec3 normal;            ///< unit shading normal, turned to face the side the ray came from
    Vec3 geometricNormal;   ///< unit normal of the triangle, turned the same way as `normal`
    bool frontFace = false; ///< the ray arrived on the triangle's front (counter-clockwise) side
    float distance = 0;     ///< ray parameter t of the hit
    Material material;      ///< the surface's material
    Color emitted;          ///< radiance the surface emits toward the ray: Ke on the front side

    explicit operator bool() const { return found; }
};

} // namespace pathlab
