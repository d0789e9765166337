#pragma once
/// The warp test of a sampling routine: many directions drawn from it, counted over the sphere,
/// against its density integrated over the same cells, by a chi-square test; and what failed, in
/// words.

#include "pathlab/warp/chi_square_fit.h"
#include "pathlab/warp/warp_histogram.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pathlab {

/// The routine under test: a direction for two numbers uniform in [0,1) (in the cells' frame:
/// z is the normal or the lobe's axis), and the density it claims for a direction.
struct WarpSampling {
    std::function<Vec3(const Vec2&)> sample;
    DirectionDensity density;
};

struct WarpTestSettings {
    SphereCells cells;
    uint64_t samples = 1000000;
    uint64_t seed = 1;
    /// The chance that a right routine fails (the test's false-fail rate).
    double alpha = 0.001;
    int thetaSteps = 32, phiSteps = 16; ///< Simpson's steps across a cell
    /// How far the density's integral may be from 1 (Simpson's error is far below it).
    double integralTolerance = 0.01;
};

/// The θ row in which the samples and the density disagree most.
struct WarpDisagreement {
    double thetaFrom = 0, thetaTo = 0; ///< in degrees
    double observed = 0, expected = 0; ///< over the row's cells
};

struct WarpTestResult {
    WarpTestSettings settings;
    std::vector<double> observed, expected; ///< per cell (SphereCells order)
    double densityIntegral = 0;             ///< over the whole sphere
    int badDensityPoints = 0;               ///< points where the density is negative or NaN
    uint64_t notDirections = 0;             ///< samples not of unit length, or NaN
    uint64_t belowSurface = 0;              ///< samples with z < 0
    ChiSquareFit fit;
    WarpDisagreement worst;
    bool passed = false;
    /// Why not, one line each, in the order a student should look: the density's sign, its
    /// integral, the samples that are no directions or below the surface, and where the
    /// samples and the density disagree.
    std::vector<std::string> problems;
};

WarpTestResult runWarpTest(const WarpSampling& routine, const WarpTestSettings& settings = {});

/// "passed: chi-square 812 on 799 degrees of freedom, p = 0.37 (a right routine fails with
/// probability 0.001)", or the problems.
std::string describeWarpTest(const WarpTestResult& result);

} // namespace pathlab
