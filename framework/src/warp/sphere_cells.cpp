#include "pathlab/warp/sphere_cells.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

namespace {
constexpr double Pi = 3.14159265358979323846;
}

double SphereCells::thetaStep() const { return Pi / thetaCells; }

double SphereCells::phiStep() const { return 2 * Pi / phiCells; }

int SphereCells::cellOf(const Vec3& w) const {
    const double theta = std::acos(std::clamp(static_cast<double>(w.z), -1.0, 1.0));
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
    if (phi < 0) phi += 2 * Pi;
    const int row = std::min(static_cast<int>(theta / thetaStep()), thetaCells - 1);
    const int column = std::min(static_cast<int>(phi / phiStep()), phiCells - 1);
    return row * phiCells + column;
}

Vec3 SphereCells::direction(double theta, double phi) {
    const double s = std::sin(theta);
    return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
            static_cast<float>(std::cos(theta))};
}

} // namespace pathlab
