#pragma once
/// How much of a glow the same from every direction a glossy (modified Phong) surface reflects:
/// the analytic values of the glossy furnaces (models/glossy_furnace*.ecs) the grader grades
/// lab 5 on.

namespace pathlab {

/// (n + 2)/(2π) ∫ cosⁿα · max(0, cos θ) dω: the fraction of a uniform glow the modified Phong
/// BRDF of exponent n reflects when its lobe's axis (the mirror direction of the view) leans
/// `tiltRadians` from the surface's normal. 1 at a tilt of 0 (all of Ks, handout 05); less where
/// part of the lobe lies below the surface and cos θ weighs the rest. The φ integral is taken in
/// closed form and the α integral by Simpson's rule, to about 1e-12.
double phongGlowReflectance(double exponent, double tiltRadians);

} // namespace pathlab
