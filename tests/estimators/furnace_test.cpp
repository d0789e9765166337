// The labs against the furnace's analytic answer: the reference solutions in the instructor's
// kit, the student's own labs in the student release (test::renderLabUnderTest).
//
// A closed enclosure whose walls all have diffuse albedo a and emit Le sees the same radiance L
// everywhere: L = Le + a·L (the walls reflect a fraction a of an irradiance π·L), so
// L = Le / (1 − a). Each term of the series Le·Σ a^k is one more bounce.
//
// With a depth limit the series is cut short. The primary hit is depth 0 and adds Le (camera
// ray); next-event estimation at a hit of depth d adds the light that arrives straight from the
// walls, a·Le, weighted by the a^d of the d diffuse bounces before it; bounce rays leave only
// from depths below maxDepth, and add no emission (next-event estimation counted it). So
//     L_maxDepth = Le + Σ_{d=0}^{maxDepth} a^(d+1)·Le = Le·Σ_{k=0}^{maxDepth+1} a^k
//                = Le·(1 − a^(maxDepth+2)) / (1 − a).
// Russian roulette is unbiased: Le / (1 − a). Its variance is finite only when each cycle of
// continuations shrinks the second moment: a diffuse continuation multiplies it by a²/q, a
// specular one (weight 1) by 1/q. In the plain furnace q = 0.5 suffices (a²/q = 0.5); a path
// through the glass sphere takes two specular hits per diffuse one, so there q = 0.9
// (0.25/0.9 · 1.23 ≈ 0.35 per cycle). At q = 0.5 the glass furnace's sample mean sits 2% low
// with an underestimated standard error: the signature of a heavy tail, not of a bias.
//
// The enclosure is a tessellated sphere: on it, next-event estimation has almost no variance,
// and the answer holds exactly for any closed polyhedron.
//
// Significance: each check is a two-sided z-test of the image mean at alpha = 1e-5
// (|z| < 4.42), with the standard error from the per-pixel sample variances.
#include "catch.h"
#include "statistics.h"
#include "test_support.h"

#include <cmath>

using namespace pathlab;

namespace {

double depthLimitedFurnace(double a, int maxDepth) {
    return (1.0 - std::pow(a, maxDepth + 2)) / (1.0 - a);
}

void expectFurnace(const std::string& scene, Lab lab, double expected,
                   const std::vector<std::string>& extra = {}) {
    std::vector<std::string> arguments = {"-c", test::modelPath(scene), "--size", "48", "48",
                                          "--spp", "32", "--seed", "1", "--lab",
                                          std::string(labName(lab))};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    const test::Estimate e = test::estimateOf(test::renderLabUnderTest(arguments));
    const double critical = test::normalCritical(1e-5);
    for (int c = 0; c < 3; ++c) {
        const double z = (e.mean[c] - expected) / std::max(e.standardError[c], 1e-6f);
        INFO(scene << " " << labName(lab) << " channel " << c << ": observed " << e.mean[c]
                   << " ± " << e.standardError[c] << ", expected " << expected << ", z = " << z);
        CHECK(std::fabs(z) < critical);
        // And close in absolute terms, so a tiny standard error cannot hide a real bias.
        CHECK(e.mean[c] == Approx(expected).epsilon(0.02));
    }
}

} // namespace

TEST_CASE("lab 1 branching: furnace at the truncated series, z-test alpha 1e-5", "[lab1]") {
    expectFurnace("furnace.ecs", Lab::Branching, depthLimitedFurnace(0.5, 3)); // 1.9375
    expectFurnace("furnace.ecs", Lab::Branching, depthLimitedFurnace(0.5, 0), {"--max-depth", "0"});
    expectFurnace("furnace_a08.ecs", Lab::Branching, depthLimitedFurnace(0.8, 5),
                  {"--max-depth", "5"});
}

TEST_CASE("lab 2 uniform pick: furnace at the truncated series, z-test alpha 1e-5", "[lab2]") {
    expectFurnace("furnace.ecs", Lab::Uniform, depthLimitedFurnace(0.5, 3));
    expectFurnace("furnace_a08.ecs", Lab::Uniform, depthLimitedFurnace(0.8, 2),
                  {"--max-depth", "2"});
}

TEST_CASE("lab 3 importance pick: furnace at the truncated series, z-test alpha 1e-5", "[lab3]") {
    expectFurnace("furnace.ecs", Lab::Importance, depthLimitedFurnace(0.5, 3));
    expectFurnace("furnace_a08.ecs", Lab::Importance, depthLimitedFurnace(0.8, 6),
                  {"--max-depth", "6"});
}

TEST_CASE("lab 4 Russian roulette: furnace at Le/(1-a), z-test alpha 1e-5", "[lab4]") {
    expectFurnace("furnace.ecs", Lab::Roulette, 2.0, {"--continue-prob", "0.5"});
    expectFurnace("furnace_a08.ecs", Lab::Roulette, 5.0, {"--continue-prob", "0.9"});
}

TEST_CASE("lab 4 Russian roulette: a mirror or glass sphere in the furnace changes nothing",
          "[lab4]") {
    expectFurnace("furnace_mirror.ecs", Lab::Roulette, 2.0, {"--continue-prob", "0.9"});
    expectFurnace("furnace_glass.ecs", Lab::Roulette, 2.0, {"--continue-prob", "0.9"});
}

TEST_CASE("the furnace test catches a wrong estimator (the test can fail)", "[lab1]") {
    // The depth-limited value is not the unbiased one: 1.9375 is 3% below 2, well outside the
    // tolerance, so the check above distinguishes the two.
    const auto result =
        test::renderLabUnderTest({"-c", test::modelPath("furnace.ecs"), "--size", "48", "48",
                                  "--spp", "32", "--seed", "1", "--lab", "branching"});
    const test::Estimate e = test::estimateOf(result);
    const double z = (e.mean.r - 2.0) / e.standardError.r;
    CHECK(std::fabs(z) > test::normalCritical(1e-5));
}
