#pragma once
/// The axis-aligned box around a scene's vertices: what a camera that was not given looks at,
/// and how far a directional light's shadow rays reach.

#include "pathlab/vec3.h"

#include <vector>

namespace pathlab {

struct BoundingBox {
    Vec3 lo, hi;

    Vec3 centre() const { return (lo + hi) * 0.5f; }
    /// The radius of the sphere around the box (half its diagonal), which holds the box however
    /// it is turned.
    float radius() const { return 0.5f * length(hi - lo); }
};

/// The box around `positions`; the unit cube around the origin when there are none, so that a
/// camera framing it is still a camera.
BoundingBox boundingBoxOf(const std::vector<Vec3>& positions);

} // namespace pathlab
