#pragma once
/// The glossy furnace (models/glossy_furnace.ecs) as a grading scene of the labs that write a
/// glossy lobe: a plate seen head-on inside a sphere that emits Le = 1 and reflects nothing, whose
/// radiance is its Ks exactly (the modified Phong BRDF reflects all of Ks about the normal;
/// handout 05). Its reference is that value, read from the scene's own material, with no
/// standard error; labs 1-4 are not graded on it.

#include "checks/grader_setup.h"

namespace pathlab::grader {

/// The scene's name in models/.
inline constexpr const char* GlossyFurnaceScene = "glossy_furnace";

/// The scene, for the labs of the kit that write a lobe; nothing when none does.
std::optional<GradingScene> glossyFurnaceScene(const Rubric& rubric);

} // namespace pathlab::grader
