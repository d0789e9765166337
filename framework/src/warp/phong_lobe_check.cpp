#include "pathlab/warp/phong_lobe_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pathlab {

namespace {

constexpr double Pi = 3.14159265358979323846;
constexpr double Degrees = 180 / Pi;
/// lobePdf's values may differ from the lobe's by float rounding: relative, and absolute as a
/// share of the lobe's peak.
constexpr double RelativeTolerance = 2e-3, PeakTolerance = 1e-5;

template <class... Values> std::string format(const char* pattern, Values... values) {
    char text[400];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

/// sampleLobe's directions against the lobe's density, and what is wrong with them in words.
WarpTestResult checkSamples(const LobeDumpExponent& e, double alpha, const std::string& step,
                            std::vector<std::string>& problems) {
    WarpTestSettings settings;
    settings.samples = e.samples.size();
    settings.alpha = alpha;
    size_t next = 0;
    WarpSampling routine;
    routine.sample = [&](const Vec2&) { return e.samples[next++]; };
    routine.density = [&](const Vec3& w) { return phongLobeDensity(w, e.exponent); };
    WarpTestResult r = runWarpTest(routine, settings);
    const double n = static_cast<double>(r.settings.samples);
    if (r.notDirections > 0)
        problems.push_back(format("sampleLobe at exponent %g: %.0f of %.0f directions are no unit "
                                  "vectors (NaN, or not of length 1) (%s)",
                                  e.exponent, static_cast<double>(r.notDirections), n,
                                  step.c_str()));
    if (r.belowSurface > 0)
        problems.push_back(format("sampleLobe at exponent %g: %.0f of %.0f directions lie below "
                                  "the lobe's plane (z < 0), where z = cos α >= 0 (%s)",
                                  e.exponent, static_cast<double>(r.belowSurface), n,
                                  step.c_str()));
    if (r.fit.pValue < alpha && r.notDirections == 0 && r.belowSurface == 0)
        problems.push_back(format("sampleLobe's directions at exponent %g do not follow the lobe "
                                  "cosⁿα (chi-square p = %.2g): most at θ %.0f-%.0f°, where %.0f "
                                  "of them fell and the lobe expects %.0f (%s)",
                                  e.exponent, r.fit.pValue, r.worst.thetaFrom, r.worst.thetaTo,
                                  r.worst.observed, r.worst.expected, step.c_str()));
    r.passed = r.notDirections == 0 && r.belowSurface == 0 && r.fit.pValue >= alpha;
    return r;
}

/// Mapped through the lobe's own CDF, (cos^(n+1) α, φ/2π) of its directions is uniform over
/// [0, 1)² (handout 05's inversion, read backwards): a chi-square test of that over
/// UniformCells² cells sees inside the warp test's cells, where a sampler whose directions are
/// few (cell centres) or clumped could match each cell's count and still not be the lobe.
constexpr int UniformCells = 50;

void checkUniformAfterCdf(const LobeDumpExponent& e, double alpha, const std::string& step,
                          std::vector<std::string>& problems) {
    std::vector<double> observed(UniformCells * UniformCells, 0.0);
    for (const Vec3& w : e.samples) {
        const double t = std::pow(std::fmax(0.0, std::fmin(1.0, double(w.z))), e.exponent + 1.0);
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0) phi += 2 * Pi;
        const int row = std::min(UniformCells - 1, static_cast<int>(t * UniformCells));
        const int column =
            std::min(UniformCells - 1, static_cast<int>(phi / (2 * Pi) * UniformCells));
        observed[static_cast<size_t>(row * UniformCells + column)] += 1;
    }
    const std::vector<double> expected(observed.size(),
                                       double(e.samples.size()) / double(observed.size()));
    const ChiSquareFit fit = chiSquareFit(observed, expected);
    if (fit.pValue >= alpha) return;
    size_t worst = 0;
    for (size_t i = 0; i < observed.size(); ++i)
        if (std::fabs(observed[i] - expected[i]) > std::fabs(observed[worst] - expected[worst]))
            worst = i;
    const double t = (double(worst / UniformCells) + 0.5) / UniformCells;
    const double phi = (double(worst % UniformCells) + 0.5) / UniformCells * 360;
    problems.push_back(format("sampleLobe's directions at exponent %g are not spread as the "
                              "lobe's: through the lobe's CDF, cos^(n+1) α and φ/2π should be "
                              "uniform in [0, 1) and are not (chi-square p = %.2g), most off near "
                              "α = %.1f°, φ = %.0f°, with %.0f directions where %.0f are expected "
                              "(%s)",
                              e.exponent, fit.pValue,
                              std::acos(std::pow(t, 1 / (e.exponent + 1.0))) * Degrees, phi,
                              observed[worst], expected[worst], step.c_str()));
}

/// lobePdf's values against the lobe's density: one line for the worst point, or for a constant
/// factor where every point inside the lobe is off by the same one.
void checkDensities(const LobeDumpExponent& e, uint64_t seed, const std::string& step,
                    std::vector<std::string>& problems) {
    const std::vector<Vec3> points =
        lobeCheckDirections(seed, e.exponent, static_cast<uint32_t>(e.densities.size()));
    const double peak = (e.exponent + 1.0) / (2 * Pi);
    double worstExcess = 0, lowestRatio = INFINITY, highestRatio = -INFINITY;
    size_t worst = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const double expected = phongLobeDensity(points[i], e.exponent);
        const double given = e.densities[i];
        const double allowed = RelativeTolerance * expected + PeakTolerance * peak;
        const double excess =
            std::isfinite(given) ? std::fabs(given - expected) / allowed : INFINITY;
        if (excess > worstExcess) {
            worstExcess = excess;
            worst = i;
        }
        if (expected > 1e-3 * peak) {
            lowestRatio = std::min(lowestRatio, given / expected);
            highestRatio = std::max(highestRatio, given / expected);
        }
    }
    if (worstExcess <= 1) return;
    if (std::isfinite(lowestRatio) && lowestRatio > 0 && highestRatio / lowestRatio < 1.01) {
        problems.push_back(format("lobePdf at exponent %g is %.4g times the lobe's density "
                                  "(n + 1)/(2π)·cosⁿα: its normalisation is off (%s)",
                                  e.exponent, 0.5 * (lowestRatio + highestRatio), step.c_str()));
        return;
    }
    const Vec3& w = points[worst];
    problems.push_back(format("lobePdf gives %.4g at α = %.1f° (exponent %g), where the lobe's "
                              "density is %.4g%s (%s)",
                              static_cast<double>(e.densities[worst]),
                              std::acos(std::fmax(-1.0, std::fmin(1.0, double(w.z)))) * Degrees,
                              e.exponent, phongLobeDensity(w, e.exponent),
                              w.z < 0 ? " (below the lobe's plane)" : "", step.c_str()));
}

} // namespace

double phongLobeDensity(const Vec3& direction, double exponent) {
    if (!(direction.z > 0)) return 0;
    return (exponent + 1) / (2 * Pi) * std::pow(static_cast<double>(direction.z), exponent);
}

PhongLobeFinding checkAgainstPhongLobe(const LobeDump& dump, uint64_t seed, double alpha,
                                       int labNumber) {
    PhongLobeFinding finding;
    const std::string number = std::to_string(labNumber);
    // Two tests of the directions per exponent share the false-fail rate.
    const double each = sidakAlpha(alpha, 2 * static_cast<int>(dump.exponents.size()));
    const std::string sampling = "TODO lab" + number + ".1";
    for (const LobeDumpExponent& e : dump.exponents) {
        const size_t before = finding.problems.size();
        finding.sampling.push_back(checkSamples(e, each, sampling, finding.problems));
        // Within the cells, once the directions are directions above the plane in them.
        if (finding.problems.size() == before)
            checkUniformAfterCdf(e, each, sampling, finding.problems);
        checkDensities(e, seed, "TODO lab" + number + ".2", finding.problems);
    }
    finding.passed = finding.problems.empty();
    return finding;
}

} // namespace pathlab
