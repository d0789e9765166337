#pragma once
/// Cutting an OBJ face of more than three corners into triangles, where the cut tinyobjloader
/// makes would cover more than the face: a concave polygon (an L, a ring drawn as one outline).

#include "pathlab/vec3.h"

#include <array>
#include <optional>
#include <vector>

namespace pathlab {

/// Whether the polygon with corners `points` (in order, around either way) turns the same way at
/// every corner, in the plane it lies nearest to. Straight corners do not count against it.
bool isConvexPolygon(const std::vector<Vec3>& points);

/// The polygon's triangles by ear clipping, each three indices into `points` in the polygon's
/// own order, so that each has the polygon's front side; nothing for a polygon that crosses
/// itself or has no area, where no ear can be cut.
std::optional<std::vector<std::array<size_t, 3>>> earClip(const std::vector<Vec3>& points);

} // namespace pathlab
