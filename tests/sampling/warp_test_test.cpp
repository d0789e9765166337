// The warp test (pathlab/warp/warp_test.h) against routines whose rightness is known: the cosine
// hemisphere and a Phong lobe pass; the mistakes lab 5's mutants make fail, each with its words.
// Each test is one chi-square test at alpha 0.001 with a fixed seed: a right routine's false-fail
// rate is 0.001 per case, and the seeds are fixed, so a pass stays a pass.
#include "catch.h"
#include "statistics.h"

#include "pathlab/cosine_hemisphere.h"
#include "pathlab/warp/warp_test.h"

#include <cmath>
#include <string>

using namespace pathlab;

namespace {

constexpr double TwoPi = 2 * 3.14159265358979323846;

/// A Phong lobe cos^n θ about +z, sampled by inverting its CDF in θ (cos θ = u^(1/(n+1))) with
/// φ uniform; `mistake` makes the routine wrong the way a student's might be.
enum class Mistake { None, DensityTwice, ThetaStretched, CosineNotCosineN, BelowSurface };

WarpSampling phongLobe(double n, Mistake mistake = Mistake::None) {
    WarpSampling routine;
    routine.sample = [n, mistake](const Vec2& u) {
        double cosTheta = std::pow(u.x, 1 / (n + 1));
        if (mistake == Mistake::ThetaStretched) // θ 1.5 times too large: a wrong inverse CDF
            cosTheta = std::cos(std::acos(std::pow(u.x, 1 / (n + 1))) * 1.5);
        if (mistake == Mistake::CosineNotCosineN) cosTheta = std::sqrt(u.x); // cos θ, not cosⁿ θ
        if (mistake == Mistake::BelowSurface && u.y < 0.01) cosTheta = -cosTheta;
        const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
        const double phi = TwoPi * u.y;
        return Vec3{static_cast<float>(sinTheta * std::cos(phi)),
                    static_cast<float>(sinTheta * std::sin(phi)), static_cast<float>(cosTheta)};
    };
    routine.density = [n, mistake](const Vec3& w) {
        if (w.z <= 0) return 0.0;
        const double density = (n + 1) / TwoPi * std::pow(static_cast<double>(w.z), n);
        return mistake == Mistake::DensityTwice ? 2 * density : density;
    };
    return routine;
}

WarpTestSettings quick() {
    WarpTestSettings settings;
    settings.samples = 200000;
    settings.cells = {16, 32};
    return settings;
}

bool mentions(const WarpTestResult& result, const std::string& words) {
    return describeWarpTest(result).find(words) != std::string::npos;
}

} // namespace

TEST_CASE("warp test: the kit's cosine hemisphere passes, its density integrating to 1",
          "[sampling][warp]") {
    WarpSampling routine;
    routine.sample = [](const Vec2& u) { return sampleCosineHemisphere({0, 0, 1}, u); };
    routine.density = [](const Vec3& w) { return w.z > 0 ? w.z / (TwoPi / 2) : 0.0; };
    const WarpTestResult result = runWarpTest(routine, quick());
    INFO(describeWarpTest(result));
    CHECK(result.passed);
    CHECK(result.densityIntegral == Approx(1).epsilon(1e-4));
    CHECK(result.belowSurface == 0);
}

TEST_CASE("warp test: Phong lobes of exponent 1 to 50 pass", "[sampling][warp]") {
    for (double n : {1.0, 10.0, 50.0}) {
        const WarpTestResult result = runWarpTest(phongLobe(n), quick());
        INFO("exponent " << n << ": " << describeWarpTest(result));
        CHECK(result.passed);
        CHECK(result.densityIntegral == Approx(1).epsilon(1e-3));
    }
}

TEST_CASE("warp test: a density twice too large is named by its integral", "[sampling][warp]") {
    const WarpTestResult result = runWarpTest(phongLobe(10, Mistake::DensityTwice), quick());
    INFO(describeWarpTest(result));
    CHECK_FALSE(result.passed);
    CHECK(result.densityIntegral == Approx(2).epsilon(1e-3));
    CHECK(mentions(result, "the density integrates to 2 over the sphere, not 1"));
}

TEST_CASE("warp test: samples that disagree with the density are found where they disagree",
          "[sampling][warp]") {
    // θ stretched by 1.5 (a wrong inverse CDF) and cos θ sampled for cos¹⁰ θ: both leave the
    // density normalised, so only the counts can tell.
    for (Mistake mistake : {Mistake::ThetaStretched, Mistake::CosineNotCosineN}) {
        const WarpTestResult result = runWarpTest(phongLobe(10, mistake), quick());
        INFO(describeWarpTest(result));
        CHECK_FALSE(result.passed);
        CHECK(result.densityIntegral == Approx(1).epsilon(1e-3));
        CHECK(mentions(result, "the samples and the density disagree"));
        CHECK(mentions(result, "most at theta"));
    }
}

TEST_CASE("warp test: samples below the surface are counted and named", "[sampling][warp]") {
    const WarpTestResult result = runWarpTest(phongLobe(10, Mistake::BelowSurface), quick());
    INFO(describeWarpTest(result));
    CHECK_FALSE(result.passed);
    CHECK(result.belowSurface > 1000);
    CHECK(mentions(result, "samples point below the surface (z < 0)"));
}

TEST_CASE("warp test: samples that are no directions are counted and named", "[sampling][warp]") {
    WarpSampling routine = phongLobe(10);
    const auto right = routine.sample;
    routine.sample = [right](const Vec2& u) {
        return u.x < 0.05f ? Vec3{std::nanf(""), 0, 1} : right(u);
    };
    const WarpTestResult result = runWarpTest(routine, quick());
    CHECK_FALSE(result.passed);
    CHECK(mentions(result, "samples are no unit direction"));
}

TEST_CASE("chi-square fit: pooled cells and Boost's p-value", "[sampling][warp]") {
    // Counts equal to their expectations: statistic 0, p-value 1.
    const ChiSquareFit same = chiSquareFit({10, 20, 30}, {10, 20, 30});
    CHECK(same.statistic == 0);
    CHECK(same.pValue == Approx(1));
    // Two cells expecting 2 and 3 are pooled into one expecting 5: 3 cells, 2 degrees of freedom.
    const ChiSquareFit pooled = chiSquareFit({2, 3, 20, 25}, {2, 3, 20, 25});
    CHECK(pooled.cells == 3);
    CHECK(pooled.degreesOfFreedom == 2);
    // Pearson's statistic and the upper tail of chi-square with 1 degree of freedom.
    const ChiSquareFit off = chiSquareFit({60, 40}, {50, 50});
    CHECK(off.statistic == Approx(4));
    CHECK(off.pValue == Approx(test::chiSquareUpperTail(1, 4.0)).epsilon(1e-9));
    CHECK(off.pValue == Approx(0.0455).epsilon(1e-3));
    // A count where nothing is expected fails outright.
    CHECK(chiSquareFit({1, 99}, {0, 100}).pValue == 0);
    CHECK(sidakAlpha(0.01, 1) == Approx(0.01));
    CHECK(sidakAlpha(0.01, 10) == Approx(1 - std::pow(0.99, 0.1)));
}
