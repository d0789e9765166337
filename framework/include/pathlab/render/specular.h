#pragma once
/// Directions of perfect specular reflection and refraction.

#include "pathlab/vec3.h"

#include <cmath>
#include <optional>

namespace pathlab {

/// Mirror reflection of the incoming direction `d` about the unit normal `n` (either side).
constexpr Vec3 reflect(const Vec3& d, const Vec3& n) { return d - n * (2.0f * dot(d, n)); }

/// Snell refraction of the unit direction `d` through a surface whose unit normal `n` faces the
/// side `d` comes from (dot(d, n) <= 0). `eta` is n_incident / n_transmitted. Returns nothing on
/// total internal reflection, when no transmitted direction exists.
inline std::optional<Vec3> refract(const Vec3& d, const Vec3& n, float eta) {
    const float cosIncident = -dot(d, n);
    const float sin2Transmitted = eta * eta * (1.0f - cosIncident * cosIncident);
    if (sin2Transmitted >= 1.0f) return std::nullopt;
    const float cosTransmitted = std::sqrt(1.0f - sin2Transmitted);
    return normalize(d * eta + n * (eta * cosIncident - cosTransmitted));
}

} // namespace pathlab
