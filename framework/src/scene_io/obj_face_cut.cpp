#include "pathlab/scene_io/obj_face_cut.h"

#include <cmath>
#include <cstddef>
#include <limits>

namespace pathlab {

namespace {

// Every computation below is in float, in tinyobjloader's order of operations: a different
// order could pick the other diagonal or another ear, and so another mesh.

/// Cuts along the shorter diagonal: v0-v2 where it is strictly shorter than v1-v3.
void cutQuad(const std::vector<ObjCorner>& face, const std::vector<float>& v,
             std::vector<ObjCornerTriangle>& triangles) {
    for (const ObjCorner& corner : face)
        if (3 * static_cast<size_t>(corner.position) + 2 >= v.size()) return;
    const auto at = [&](int k, int axis) {
        return v[3 * static_cast<size_t>(face[k].position) + axis];
    };
    const float e02x = at(2, 0) - at(0, 0), e02y = at(2, 1) - at(0, 1), e02z = at(2, 2) - at(0, 2);
    const float e13x = at(3, 0) - at(1, 0), e13y = at(3, 1) - at(1, 1), e13z = at(3, 2) - at(1, 2);
    const float sqr02 = e02x * e02x + e02y * e02y + e02z * e02z;
    const float sqr13 = e13x * e13x + e13y * e13y + e13z * e13z;
    if (sqr02 < sqr13) {
        triangles.push_back({face[0], face[1], face[2]});
        triangles.push_back({face[0], face[2], face[3]});
    } else {
        triangles.push_back({face[0], face[1], face[3]});
        triangles.push_back({face[1], face[2], face[3]});
    }
}

/// The two axes the ear clipping works in: those across the normal of the first corner (of
/// consecutive corners k, k+1, k+2) that is not straight.
std::array<size_t, 2> clippingAxes(const std::vector<ObjCorner>& face,
                                   const std::vector<float>& v) {
    std::array<size_t, 2> axes = {1, 2};
    const size_t n = face.size();
    for (size_t k = 0; k < n; ++k) {
        const size_t i0 = size_t(face[k % n].position), i1 = size_t(face[(k + 1) % n].position),
                     i2 = size_t(face[(k + 2) % n].position);
        if (3 * i0 + 2 >= v.size() || 3 * i1 + 2 >= v.size() || 3 * i2 + 2 >= v.size()) continue;
        const float e0x = v[i1 * 3] - v[i0 * 3], e0y = v[i1 * 3 + 1] - v[i0 * 3 + 1],
                    e0z = v[i1 * 3 + 2] - v[i0 * 3 + 2];
        const float e1x = v[i2 * 3] - v[i1 * 3], e1y = v[i2 * 3 + 1] - v[i1 * 3 + 1],
                    e1z = v[i2 * 3 + 2] - v[i1 * 3 + 2];
        const float cx = std::fabs(e0y * e1z - e0z * e1y);
        const float cy = std::fabs(e0z * e1x - e0x * e1z);
        const float cz = std::fabs(e0x * e1y - e0y * e1x);
        const float epsilon = std::numeric_limits<float>::epsilon();
        if (cx > epsilon || cy > epsilon || cz > epsilon) {
            if (!(cx > cy && cx > cz)) {
                axes[0] = 0;
                if (cz > cx && cz > cy) axes[1] = 1;
            }
            break;
        }
    }
    return axes;
}

/// Whether (x, y) lies inside the triangle (vx, vy), by crossings (W. R. Franklin's pnpoly).
bool insideTriangle(const float* vx, const float* vy, float x, float y) {
    bool inside = false;
    for (int i = 0, j = 2; i < 3; j = i++)
        if (((vy[i] > y) != (vy[j] > y)) &&
            (x < (vx[j] - vx[i]) * (y - vy[i]) / (vy[j] - vy[i]) + vx[i]))
            inside = !inside;
    return inside;
}

/// A vertex's coordinate along `axis`, 0 beyond the vertices read so far.
float coordinate(const std::vector<float>& v, const ObjCorner& corner, size_t axis) {
    const size_t at = size_t(corner.position) * 3 + axis;
    return at < v.size() ? v[at] : 0.0f;
}

/// Whether the corners `guess`, +1, +2 of `left` make an ear: turning the way the sign of its
/// (origin-dependent) area says, no other corner inside it.
bool isEar(const std::vector<ObjCorner>& left, size_t guess, const std::vector<float>& v,
           const std::array<size_t, 2>& axes) {
    const size_t n = left.size();
    float vx[3], vy[3];
    for (size_t k = 0; k < 3; ++k) {
        const ObjCorner& corner = left[(guess + k) % n];
        const bool known = size_t(corner.position) * 3 + axes[0] < v.size() &&
                           size_t(corner.position) * 3 + axes[1] < v.size();
        vx[k] = known ? v[size_t(corner.position) * 3 + axes[0]] : 0.0f;
        vy[k] = known ? v[size_t(corner.position) * 3 + axes[1]] : 0.0f;
    }
    const float e0x = vx[1] - vx[0], e0y = vy[1] - vy[0];
    const float e1x = vx[2] - vx[1], e1y = vy[2] - vy[1];
    const float cross = e0x * e1y - e0y * e1x;
    const float area = (vx[0] * vy[1] - vy[0] * vx[1]) * 0.5f;
    if (cross * area < 0.0f) return false;
    for (size_t other = 3; other < n; ++other) {
        const ObjCorner& corner = left[(guess + other) % n];
        if (size_t(corner.position) * 3 + axes[0] >= v.size() ||
            size_t(corner.position) * 3 + axes[1] >= v.size())
            continue;
        if (insideTriangle(vx, vy, coordinate(v, corner, axes[0]), coordinate(v, corner, axes[1])))
            return false;
    }
    return true;
}

/// Cuts ears off from corner `guess` on, giving up after a round without one; what is left,
/// if it is a triangle, is the last one.
void clipEars(const std::vector<ObjCorner>& face, const std::vector<float>& v,
              std::vector<ObjCornerTriangle>& triangles) {
    const std::array<size_t, 2> axes = clippingAxes(face, v);
    std::vector<ObjCorner> left = face;
    size_t guess = 0;
    size_t triesLeft = face.size(), previousSize = left.size();
    while (left.size() > 3 && triesLeft > 0) {
        const size_t n = left.size();
        if (guess >= n) guess -= n;
        if (previousSize != n) {
            previousSize = n;
            triesLeft = n;
        } else {
            --triesLeft;
        }
        if (!isEar(left, guess, v, axes)) {
            ++guess;
            continue;
        }
        triangles.push_back({left[guess % n], left[(guess + 1) % n], left[(guess + 2) % n]});
        left.erase(left.begin() + static_cast<std::ptrdiff_t>((guess + 1) % n));
    }
    if (left.size() == 3) triangles.push_back({left[0], left[1], left[2]});
}

} // namespace

void cutObjFace(const std::vector<ObjCorner>& face, const std::vector<float>& positions,
                std::vector<ObjCornerTriangle>& triangles) {
    if (face.size() < 3) return;
    if (face.size() == 3) {
        triangles.push_back({face[0], face[1], face[2]});
    } else if (face.size() == 4) {
        cutQuad(face, positions, triangles);
    } else {
        clipEars(face, positions, triangles);
    }
}

} // namespace pathlab
