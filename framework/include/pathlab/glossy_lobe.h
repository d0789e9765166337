#pragma once
/// The glossy component of lab 5: a Phong lobe about the mirror direction.

#include "pathlab/color.h"
#include "pathlab/constants.h"
#include "pathlab/material.h"

#include <cmath>

namespace pathlab {

/// The BRDF of the glossy component of a material with m.Ns = n > 0: the modified Phong BRDF
/// of Lafortune and Willems (1994),
///
///     f = Ks · (n + 2) / (2π) · cosⁿ α,
///
/// with α the angle between the direction the light leaves in and the mirror reflection of the
/// direction it came from (the lobe's axis), and 0 where cos α <= 0. The factor (n + 2) / (2π)
/// makes it reflect at most Ks of the light that arrives (handout 05 shows why); `cosAlpha` is
/// the z of a direction in the lobe's frame.
inline Color phongBrdf(const Material& m, float cosAlpha) {
    if (!(cosAlpha > 0)) return Color();
    return m.Ks * ((m.Ns + 2.0f) / (2.0f * Pi) * std::pow(cosAlpha, m.Ns));
}

} // namespace pathlab
