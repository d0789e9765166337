#pragma once
/// Cosine-weighted hemisphere sampling (Malley's method: uniform disk, projected up).

#include "pathlab/constants.h"
#include "pathlab/orthonormal_basis.h"
#include "pathlab/small_angle_sin_cos.h"
#include "pathlab/vec3.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

/// A direction in the hemisphere around the unit vector `normal`, with density
/// pdf(ω) = cos θ / π (θ measured from `normal`). Handout 01 shows why, with this pdf,
/// a diffuse bounce carries the weight Kd and no π.
inline Vec3 sampleCosineHemisphere(const Vec3& normal, Vec2 u) {
    // Concentric mapping of the square onto the disk (Shirley & Chiu), which keeps strata compact.
    // The angle is π/4·t with |t| <= 1 in the wedges around x (φ) and around y (π/2 - φ, whose
    // cosine and sine are φ's sine and cosine).
    const float sx = 2.0f * u.x - 1.0f;
    const float sy = 2.0f * u.y - 1.0f;
    float dx = 0, dy = 0;
    if (std::fabs(sx) > std::fabs(sy)) {
        const SinCos phi = sinCosSmallAngle((Pi / 4) * (sy / sx));
        dx = sx * phi.cos;
        dy = sx * phi.sin;
    } else if (sy != 0) {
        const SinCos phi = sinCosSmallAngle((Pi / 4) * (sx / sy));
        dx = sy * phi.sin;
        dy = sy * phi.cos;
    }
    const float dz = std::sqrt(std::max(0.0f, 1.0f - dx * dx - dy * dy));
    return OrthonormalBasis(normal).toWorld({dx, dy, dz});
}

/// The density of sampleCosineHemisphere, per unit solid angle.
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0 ? cosTheta * InvPi : 0.0f; }

} // namespace pathlab
