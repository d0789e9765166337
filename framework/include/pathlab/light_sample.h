#pragma once
/// Lab 6: one sample of the scene's lights, with its density per unit solid angle, for
/// multiple importance sampling (handout 06).

#include "pathlab/color.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// A direction toward a point chosen on a light, what arrives along it, and how likely it was:
/// what ctx.sampleLight(hit) returns. The light-sampling estimate of what a BRDF f reflects is
///
///     f · radiance · cos θ / pdf,
///
/// θ the angle between `direction` and the surface's normal.
struct LightSample {
    Vec3 direction;     ///< unit, from the surface toward the chosen point
    float distance = 0; ///< to that point (for a directional light, past the scene)
    /// The light's radiance arriving along `direction`: black when something is in the way,
    /// when the point is seen from the light's back, or when it lies below the surface.
    Color radiance;
    /// The density of `direction` per unit solid angle at the surface: the light's pick
    /// probability times the point's density per unit area, times distance² / cos θ' (θ' the
    /// angle at the light). For a point or directional light, which no bounce can ever find,
    /// `delta` is true and `pdf` is the pick probability alone: `radiance` is then the
    /// intensity / distance², or the irradiance, arriving. 0 when there are no lights.
    float pdf = 0;
    bool delta = false; ///< a point or directional light: only light sampling can find it
    /// cos θ', the cosine at the chosen point between its normal and the way back to the
    /// surface (1 for a point or directional light): pdf = pick · distance² / (area · cos θ').
    float cosAtLight = 1;
};

/// The two strategies lab 6 combines at a glossy surface. The viewer's --strategy (and the
/// handout's three-panel figure) can keep one of them alone: see ctx.strategyWeight.
enum class Strategy {
    Light, ///< next-event estimation: a point sampled on a light
    Lobe,  ///< the glossy lobe's own sampling (lab 5's sampleLobe)
};

/// Which strategies a render uses: both (multiple importance sampling, the default) or one.
enum class StrategyChoice { Both, LightOnly, LobeOnly };

} // namespace pathlab
