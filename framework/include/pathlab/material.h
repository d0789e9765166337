#pragma once
/// Surface materials as the MTL file gives them.

#include "pathlab/color.h"

namespace pathlab {

/// What a surface does with light. Each component is a reflectance in [0,1] per channel and
/// Kd + Ks + Kt <= 1 for an energy-conserving material.
struct Material {
    Color Kd;        ///< diffuse (Lambertian) albedo: reflects Kd/π of irradiance as radiance
    Color Ks;        ///< specular reflectance: a perfect mirror, or a glossy lobe where Ns > 0
    Color Kt;        ///< perfect specular transmittance (MTL `Kt` or `Tf`)
    float Ni = 1.0f; ///< index of refraction of the inside (the side the normal points away from)
    Color Ke;        ///< emitted radiance, from the front side only
    /// The exponent of Ks's glossy (Phong) lobe about the mirror direction, from an MTL material
    /// with `illum 2` and `Ns`; 0 where Ks is a perfect mirror. Lab 5 uses it (handout
    /// 05); labs 1–4 take every Ks for a mirror, as their handouts say.
    float Ns = 0.0f;
};

} // namespace pathlab
