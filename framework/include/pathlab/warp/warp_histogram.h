#pragma once
/// What the warp test compares: the samples counted in the sphere's cells, and the density
/// integrated over each of them.

#include "pathlab/warp/sphere_cells.h"

#include <functional>
#include <vector>

namespace pathlab {

/// A density in solid angle (per steradian) at a unit direction.
using DirectionDensity = std::function<double(const Vec3&)>;

/// ∫ density dω over each cell (dω = sin θ dθ dφ), by Simpson's rule with `thetaSteps` and
/// `phiSteps` (even) steps across each cell: θ finer, since a narrow lobe varies fastest in θ.
/// A density that is negative or not a number somewhere counts as such in `badPoints`.
std::vector<double> integratedDensity(const SphereCells& cells, const DirectionDensity& density,
                                      int thetaSteps, int phiSteps, int& badPoints);

} // namespace pathlab
