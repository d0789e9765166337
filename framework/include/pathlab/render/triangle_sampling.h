#pragma once
/// Uniform points on triangles, for sampling area lights.

#include "pathlab/vec3.h"

#include <cmath>

namespace pathlab {

/// A point uniformly distributed over the triangle (a, b, c), density 1/area. Uses the
/// square-root warp of Osada et al. ("Shape distributions", 2002).
inline Vec3 sampleTriangleUniform(const Vec3& a, const Vec3& b, const Vec3& c, Vec2 u) {
    const float su = std::sqrt(u.x);
    const float wa = 1.0f - su;
    const float wb = su * (1.0f - u.y);
    const float wc = su * u.y;
    return a * wa + b * wb + c * wc;
}

inline float triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    return 0.5f * length(cross(b - a, c - a));
}

} // namespace pathlab
