#pragma once
/// The glossy furnaces (models/glossy_furnace.ecs and glossy_furnace_tilted.ecs) as grading
/// scenes of the labs that write a glossy lobe: a plate inside a sphere that emits Le = 1 and
/// reflects nothing, seen head-on, where its radiance is its Ks exactly (the modified Phong BRDF
/// reflects all of Ks about the normal; handout 05), and at 60 degrees, where it is Ks·ρ(β) with
/// ρ the lobe's reflectance above the surface (pathlab/warp/phong_albedo.h) and a mirror would
/// still show Ks: the view that tells a glossy bounce from a mirror one. Each reference is its
/// value, from the scene's own material and camera, with no standard error; labs 1-4 are not
/// graded on them.

#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The scenes' names in models/.
inline constexpr const char* GlossyFurnaceScenes[] = {"glossy_furnace", "glossy_furnace_tilted"};

/// The scenes, for the labs of the kit that write a lobe; none when no lab does.
std::vector<GradingScene> glossyFurnaceScenes(const Rubric& rubric);

/// A number that differs from one submission of a lab to another and is the same each time the
/// same lab is graded again: the grading's seed and the lab's own code (its library in the
/// sandbox, else the viewer that links it). The lobe check's inputs and the tilted furnace's
/// variant are drawn from it, so that no answer one grading shows fits the next submission.
uint64_t labVariantSeed(const GraderSetup& setup, Lab lab);

/// glossy_furnace_tilted as the lab `seed` is graded on it: the plate's Phong exponent drawn in
/// [6, 40) and the view's angle from its normal in [35, 70) degrees, written into `scratch` (the
/// mesh copied, its material and camera rewritten) with its analytic value. A lab cannot answer
/// it from a table of the public scene's value.
GradingScene tiltedGlossyFurnaceVariant(const Rubric& rubric, uint64_t seed,
                                        const std::string& scratch);

} // namespace pathlab::grader
