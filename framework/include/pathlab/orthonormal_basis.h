#pragma once
/// A local frame around a unit normal, for turning hemisphere samples into world directions.

#include "pathlab/vec3.h"

#include <cmath>

namespace pathlab {

/// Tangent, bitangent and normal of a right-handed frame. Built with the branchless method of
/// Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017), which has no
/// singularity at any normal.
struct OrthonormalBasis {
    Vec3 tangent, bitangent, normal;

    explicit OrthonormalBasis(const Vec3& n) : normal(n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        tangent = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        bitangent = {b, sign + n.y * n.y * a, -n.y};
    }

    /// Local (x, y, z) with z along the normal, to world space.
    Vec3 toWorld(const Vec3& local) const {
        return tangent * local.x + bitangent * local.y + normal * local.z;
    }

    /// World space to local (x, y, z), z along the normal.
    Vec3 toLocal(const Vec3& world) const {
        return {dot(world, tangent), dot(world, bitangent), dot(world, normal)};
    }
};

} // namespace pathlab
