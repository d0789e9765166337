#pragma once
/// Surface materials as the MTL file gives them.

#include "pathlab/color.h"

namespace pathlab {

/// What a surface does with light. Each component is a reflectance in [0,1] per channel and
/// Kd + Ks + Kt <= 1 for an energy-conserving material.
struct Material {
    Color Kd;        ///< diffuse (Lambertian) albedo: reflects Kd/π of irradiance as radiance
    Color Ks;        ///< perfect mirror reflectance
    Color Kt;        ///< perfect specular transmittance (MTL `Kt` or `Tf`)
    float Ni = 1.0f; ///< index of refraction of the inside (the side the normal points away from)
    Color Ke;        ///< emitted radiance, from the front side only
};

} // namespace pathlab
