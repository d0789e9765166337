#pragma once
/// The sphere of directions cut into cells of equal steps in θ (from +z, the surface's normal or
/// the lobe's axis) and in φ (about z, from +x): where the warp test counts samples and
/// integrates a density.

#include "pathlab/vec3.h"

namespace pathlab {

struct SphereCells {
    int thetaCells = 20; ///< over [0, π]: the lower half are the directions below the surface
    int phiCells = 40;   ///< over [0, 2π)

    int count() const { return thetaCells * phiCells; }
    double thetaStep() const;
    double phiStep() const;
    /// The cell holding unit direction `w`: θ row by θ row.
    int cellOf(const Vec3& w) const;
    int thetaRow(int cell) const { return cell / phiCells; }
    /// The direction at (θ, φ).
    static Vec3 direction(double theta, double phi);
};

} // namespace pathlab
