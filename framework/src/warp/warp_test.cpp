#include "pathlab/warp/warp_test.h"

#include "pathlab/random_stream.h"

#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

constexpr double Degrees = 180 / 3.14159265358979323846;

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, a, b, c, d);
    return text;
}

/// Counts the routine's samples in the cells; those that are no unit direction are counted
/// apart and left out.
void countSamples(const WarpSampling& routine, WarpTestResult& result) {
    const WarpTestSettings& s = result.settings;
    result.observed.assign(static_cast<size_t>(s.cells.count()), 0.0);
    RandomStream random(s.seed);
    for (uint64_t i = 0; i < s.samples; ++i) {
        const float u = random.nextFloat();
        const Vec2 uv{u, random.nextFloat()};
        const Vec3 w = routine.sample(uv);
        const double length =
            std::sqrt(static_cast<double>(w.x) * w.x + static_cast<double>(w.y) * w.y +
                      static_cast<double>(w.z) * w.z);
        if (!(std::abs(length - 1) < 1e-3)) {
            ++result.notDirections;
            continue;
        }
        if (w.z < 0) ++result.belowSurface;
        result.observed[static_cast<size_t>(s.cells.cellOf(w))] += 1;
    }
}

WarpDisagreement worstRow(const WarpTestResult& result) {
    const SphereCells& cells = result.settings.cells;
    WarpDisagreement worst;
    double worstScore = -1;
    for (int row = 0; row < cells.thetaCells; ++row) {
        double observed = 0, expected = 0;
        for (int column = 0; column < cells.phiCells; ++column) {
            const size_t cell = static_cast<size_t>(row * cells.phiCells + column);
            observed += result.observed[cell];
            expected += result.expected[cell];
        }
        const double score = std::abs(observed - expected) / std::sqrt(std::max(expected, 1.0));
        if (score > worstScore) {
            worstScore = score;
            worst = {row * cells.thetaStep() * Degrees, (row + 1) * cells.thetaStep() * Degrees,
                     observed, expected};
        }
    }
    return worst;
}

std::vector<std::string> problemsOf(const WarpTestResult& r) {
    std::vector<std::string> problems;
    const double n = static_cast<double>(r.settings.samples);
    if (r.badDensityPoints > 0)
        problems.push_back(format("the density is negative or NaN at %.0f of the points it was "
                                  "integrated at",
                                  r.badDensityPoints));
    if (std::abs(r.densityIntegral - 1) > r.settings.integralTolerance)
        problems.push_back(format("the density integrates to %.4g over the sphere, not 1: it is "
                                  "not normalised (%.4g times too large)",
                                  r.densityIntegral, r.densityIntegral));
    if (r.notDirections > 0)
        problems.push_back(format("%.0f of %.0f samples are no unit direction (NaN, or not of "
                                  "length 1)",
                                  static_cast<double>(r.notDirections), n));
    if (r.belowSurface > 0)
        problems.push_back(format("%.0f of %.0f samples point below the surface (z < 0)",
                                  static_cast<double>(r.belowSurface), n));
    if (r.fit.pValue < r.settings.alpha) {
        const WarpDisagreement& w = r.worst;
        problems.push_back(format("the samples and the density disagree (chi-square p = %.2g); "
                                  "most at theta %.0f-%.0f degrees",
                                  r.fit.pValue, w.thetaFrom, w.thetaTo) +
                           format(", where %.0f samples fell and the density expects %.0f",
                                  w.observed, w.expected));
    }
    return problems;
}

} // namespace

WarpTestResult runWarpTest(const WarpSampling& routine, const WarpTestSettings& settings) {
    WarpTestResult result;
    result.settings = settings;
    countSamples(routine, result);
    const std::vector<double> integrals =
        integratedDensity(settings.cells, routine.density, settings.thetaSteps, settings.phiSteps,
                          result.badDensityPoints);
    const double counted = static_cast<double>(settings.samples - result.notDirections);
    for (double integral : integrals) {
        result.densityIntegral += integral;
        result.expected.push_back(integral * counted);
    }
    result.fit = chiSquareFit(result.observed, result.expected);
    result.worst = worstRow(result);
    result.problems = problemsOf(result);
    result.passed = result.problems.empty();
    return result;
}

std::string describeWarpTest(const WarpTestResult& result) {
    const ChiSquareFit& fit = result.fit;
    if (result.passed)
        return format("passed: chi-square %.4g on %.0f degrees of freedom, p = %.2g (a right "
                      "routine fails with probability %.2g)",
                      fit.statistic, fit.degreesOfFreedom, fit.pValue, result.settings.alpha);
    std::string text = "failed:";
    for (const std::string& problem : result.problems) text += "\n  " + problem;
    return text;
}

} // namespace pathlab
