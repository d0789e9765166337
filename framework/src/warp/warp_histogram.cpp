#include "pathlab/warp/warp_histogram.h"

#include <cmath>

namespace pathlab {

namespace {

/// Simpson's weights 1 4 2 4 ... 4 1 over `steps` (even) steps.
double simpsonWeight(int i, int steps) {
    if (i == 0 || i == steps) return 1;
    return i % 2 == 1 ? 4 : 2;
}

} // namespace

std::vector<double> integratedDensity(const SphereCells& cells, const DirectionDensity& density,
                                      int thetaSteps, int phiSteps, int& badPoints) {
    badPoints = 0;
    std::vector<double> integrals(static_cast<size_t>(cells.count()), 0.0);
    const double dTheta = cells.thetaStep() / thetaSteps, dPhi = cells.phiStep() / phiSteps;
    for (int row = 0; row < cells.thetaCells; ++row)
        for (int column = 0; column < cells.phiCells; ++column) {
            double sum = 0;
            for (int i = 0; i <= thetaSteps; ++i) {
                const double theta = row * cells.thetaStep() + i * dTheta;
                for (int j = 0; j <= phiSteps; ++j) {
                    const double phi = column * cells.phiStep() + j * dPhi;
                    double value = density(SphereCells::direction(theta, phi));
                    if (!(value >= 0)) { // negative or NaN: counted, and taken as 0
                        ++badPoints;
                        value = 0;
                    }
                    sum += simpsonWeight(i, thetaSteps) * simpsonWeight(j, phiSteps) * value *
                           std::sin(theta);
                }
            }
            integrals[static_cast<size_t>(row * cells.phiCells + column)] = sum * dTheta * dPhi / 9;
        }
    return integrals;
}

} // namespace pathlab
