// Speed in a build without the reference solutions: a lab's timed runs against the solutions'
// stored figures, carried to this machine by the kit's own cost of a ray.
#include "catch.h"
#include "messages.h"

#include "checks/kit_ray_cost.h"
#include "checks/local_speed_estimate.h"

#include "pathlab/support/input_error.h"

#include <cmath>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

/// Lab 2's reference as stored: 1 camera + 0.93 bounce + 1.62 shadow rays per sample, 2e6
/// samples per CPU-second on a machine where the kit's ray cost 1e-7 s.
StoredSolutionSpeed storedUniform() {
    StoredSolutionSpeed stored;
    stored.samplesPerCpuSecond[Lab::Uniform] = 2e6;
    stored.rays[Lab::Uniform] = {1, 0.93, 1.62};
    stored.raysKnown = true;
    stored.kitCpuSecondsPerRay = 1e-7;
    return stored;
}

} // namespace

TEST_CASE("a lab like the reference is estimated at its speed, on a machine twice as slow",
          "[grader]") {
    Rubric rubric;
    // This machine takes twice the kit's time per ray: the reference would do 1e6 here.
    const LocalSpeedEstimate e =
        estimateSpeedLocally(rubric, Lab::Uniform, 1e6, {1, 0.93, 1.62}, storedUniform(), 2e-7);
    CHECK(e.scaledByRayCost);
    CHECK(e.ratio == Approx(1.0));
    CHECK(e.raysRatio == Approx(1.0));
    CHECK(e.workPerRayRatio == Approx(1.0));
    CHECK(e.causes.empty());
    CHECK_FALSE(e.atRisk);
}

TEST_CASE("a lab 2 that traces its black components is at risk, and told why", "[grader]") {
    Rubric rubric;
    // 1.7 times the bounce rays, and the shadow rays that come with them: at the same cost per
    // ray, about 0.6 of the reference's samples per CPU-second.
    const RaysPerSample rays{1, 1.58, 2.75};
    const double rate = 2e6 * 3.55 / 5.33; // each ray at the reference's cost
    const LocalSpeedEstimate e =
        estimateSpeedLocally(rubric, Lab::Uniform, rate, rays, storedUniform(), 1e-7);
    CHECK(e.ratio == Approx(3.55 / 5.33).epsilon(0.01));
    CHECK(e.ratio < rubric.minSpeedRatio);
    CHECK(e.atRisk);
    REQUIRE_FALSE(e.causes.empty());
    CHECK(contains(e.causes.front(), "traces 1.7× the bounce rays of the lab's estimator "
                                     "(1.58 per sample against 0.93): a black component traced?"));
}

TEST_CASE("work per ray beyond the reference's is named, rays alike", "[grader]") {
    Rubric rubric;
    // The same rays, at a third of the samples per CPU-second the reference would do here.
    const LocalSpeedEstimate e =
        estimateSpeedLocally(rubric, Lab::Uniform, 2e6 / 3, {1, 0.93, 1.62}, storedUniform(), 1e-7);
    CHECK(e.workPerRayRatio == Approx(3.0));
    CHECK(e.atRisk);
    REQUIRE(e.causes.size() == 1);
    CHECK(contains(e.causes.front(), "3× the reference's CPU time per ray"));
}

TEST_CASE("slower without a cause is not called at risk: the estimate crosses machines",
          "[grader]") {
    Rubric rubric;
    const LocalSpeedEstimate e = estimateSpeedLocally(rubric, Lab::Uniform, 2e6 * 0.7,
                                                      {1, 0.93, 1.62}, storedUniform(), 1e-7);
    CHECK(e.ratio == Approx(0.7));
    CHECK(e.causes.empty());
    CHECK_FALSE(e.atRisk);
}

TEST_CASE("without a stored cost of a ray, rays per sample alone", "[grader]") {
    Rubric rubric;
    StoredSolutionSpeed stored = storedUniform();
    stored.kitCpuSecondsPerRay = 0;
    const LocalSpeedEstimate e =
        estimateSpeedLocally(rubric, Lab::Uniform, 5e5, {1, 1.58, 2.75}, stored, 1e-7);
    CHECK_FALSE(e.scaledByRayCost);
    CHECK(e.ratio == Approx(3.55 / 5.33).epsilon(0.01));
    CHECK(e.atRisk);
    // And nothing stored at all: no estimate.
    CHECK(estimateSpeedLocally(rubric, Lab::Uniform, 5e5, {1, 1.58, 2.75}, {}, 1e-7).ratio == 0);
}

TEST_CASE("extra shadow rays are named as next-event estimation repeated", "[grader]") {
    Rubric rubric;
    const LocalSpeedEstimate e =
        estimateSpeedLocally(rubric, Lab::Uniform, 1e6, {1, 0.93, 3.5}, storedUniform(), 1e-7);
    REQUIRE_FALSE(e.causes.empty());
    CHECK(contains(e.causes.front(), "ctx.directLight(hit) called more than once per hit?"));
}

TEST_CASE("the kit's own cost of a ray is measured on a scene", "[grader]") {
    const double perRay = kitCpuSecondsPerRay(
        std::string(PATHLAB_MODELS_DIR) + "/cornell_box_VI2_Specular.ecs", 64, 64, 1);
    // A figure, not a timing verdict: positive, and far from absurd on any machine.
    CHECK(perRay > 1e-9);
    CHECK(perRay < 1e-3);
    CHECK_THROWS_AS(kitCpuSecondsPerRay("/nonexistent/scene.ecs", 64, 64, 1), InputError);
}
