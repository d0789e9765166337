#pragma once
/// The triangles an OBJ face becomes, cut exactly as tinyobjloader 2.0.0rc10 cut it (with
/// triangulate=true), through which PathLab's scenes were loaded until it read them itself: a
/// quad along its shorter diagonal, a larger face by tinyobjloader's own ear clipping. PathLab
/// cuts concave faces itself beforehand (polygon_triangulation.h); what reaches this is a
/// triangle, a convex face or one PathLab could not cut.

#include <array>
#include <vector>

namespace pathlab {

/// A face corner: 0-based indices of its position and normal (-1: none).
struct ObjCorner {
    int position = -1;
    int normal = -1;
};

using ObjCornerTriangle = std::array<ObjCorner, 3>;

/// Appends the triangles of `face` to `triangles`. `positions` (x, y, z of each vertex) are the
/// vertices read so far; a quad with a corner beyond them is left out, as tinyobjloader left it
/// out, and so is a face of fewer than 3 corners.
void cutObjFace(const std::vector<ObjCorner>& face, const std::vector<float>& positions,
                std::vector<ObjCornerTriangle>& triangles);

} // namespace pathlab
