#pragma once
/// Rays, and the record of how each one was made.

#include "pathlab/vec3.h"

namespace pathlab {

/// How a ray came to be. It decides whether emission found by the ray may be added:
/// next-event estimation already counted the light a diffuse bounce would find, and nothing
/// counted what a specular or glossy bounce finds.
enum class RayKind {
    Camera,   ///< a primary ray from the eye
    Diffuse,  ///< left a surface in a cosine-sampled direction
    Specular, ///< left a surface by mirror reflection or refraction
    Glossy,   ///< left a surface in a direction sampled from a glossy lobe (lab 5)
};

/// A half-line origin + t·direction, t > 0. `direction` is unit length.
struct Ray {
    Vec3 origin;
    Vec3 direction;
    RayKind kind = RayKind::Camera;
};

} // namespace pathlab
