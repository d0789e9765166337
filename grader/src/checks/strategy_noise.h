#pragma once
/// Lab 6's noise check, after Veach: on veach_plates, tile by tile, the lab's per-sample variance
/// against the better of the two strategies alone, the light's and the lobe's, each rendered by
/// the reference solution (viewer --strategy light, lobe) at the same size, spp and seed count.
///
/// Multiple importance sampling with the balance or power heuristic is never much noisier than
/// the better strategy for any integrand (Veach 1997, theorem 9.2), and far quieter than the
/// worse one: a lab whose weights favour the wrong strategy (its light density left in area
/// measure, a constant weight such as the stub's one half) is noisier than the better strategy
/// by a factor of several on the plates where the two differ, while its mean, which the weights
/// do not change as long as they add up to one, passes the correctness check.

#include "checks/grader_setup.h"
#include "checks/strategy_tiles.h"

#include <string>
#include <vector>

namespace pathlab::grader {

/// Whether `lab` combines the two strategies through ctx.strategyWeight (lab 6).
bool combinesStrategies(Lab lab);

/// Renders veach_plates with the student's lab and with the solution's two strategies alone.
StrategyTiles measureStrategyTiles(const GraderSetup& setup, Lab lab);

} // namespace pathlab::grader
