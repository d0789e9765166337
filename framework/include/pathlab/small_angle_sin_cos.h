#pragma once
/// Sine and cosine of angles up to π/4 together, as polynomials: the angles cosine sampling needs.

namespace pathlab {

struct SinCos {
    float sin, cos;
};

/// sin x and cos x for |x| <= π/4, within a few ulp of the exact values: their Taylor series to
/// x⁹ and x⁸, whose first terms left out are below 2e-9 and 2.5e-8 there (an ulp of 0.7 is 6e-8).
/// Inline rather than a call to the C library's sincosf, which costs a call per diffuse bounce, and
/// whose last bits differ between libraries: one reason fewer for images to differ between
/// platforms.
inline SinCos sinCosSmallAngle(float x) {
    const float x2 = x * x;
    const float sinSeries =
        1.0f / 120 + x2 * (-1.0f / 5040 + x2 * (1.0f / 362880)); // x⁵/5! - x⁷/7! + x⁹/9!, over x⁵
    const float cosSeries = 1.0f / 24 + x2 * (-1.0f / 720 + x2 * (1.0f / 40320)); // over x⁴
    return {x + x * x2 * (-1.0f / 6 + x2 * sinSeries), 1.0f + x2 * (-0.5f + x2 * cosSeries)};
}

} // namespace pathlab
