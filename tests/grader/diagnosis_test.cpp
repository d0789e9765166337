// The diagnosis shared by the grader and the lab tests, against the furnace series worked by hand
// and the values known bugs give.
#include "catch.h"
#include "messages.h"

#include "diagnosis/diagnosis.h"
#include "diagnosis/diagnosis_table.h"

#include <cmath>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

const FurnaceModel diffuse{FurnaceWalls::Diffuse, 0.5, 3, 0.8};
const FurnaceModel mirror{FurnaceWalls::Mirror, 0.5, 3, 0.8};

/// The first (likeliest) cause, or "" when there is none, for a lab that still reports open
/// TODO steps (`stepsOpen`) or not.
std::string likeliest(Lab lab, const std::vector<FurnaceObservation>& observations,
                      bool stepsOpen = true) {
    const std::vector<std::string> causes = likelyFurnaceCauses(lab, observations, stepsOpen);
    return causes.empty() ? "" : causes.front();
}

} // namespace

TEST_CASE("the furnaces' values for correct labs are the closed forms", "[grader]") {
    // Diffuse walls: Le·(1 − a^(D+2))/(1 − a) for labs 1–3, Le/(1 − a) for lab 4 (Le = 1).
    CHECK(correctFurnaceValue(Lab::Branching, diffuse) == Approx(1.9375));
    CHECK(correctFurnaceValue(Lab::Importance, {FurnaceWalls::Diffuse, 0.8, 5, 0.8}) ==
          Approx((1 - std::pow(0.8, 7)) / 0.2));
    CHECK(correctFurnaceValue(Lab::Roulette, diffuse) == Approx(2.0).epsilon(1e-6));
    // Mirror walls: Le at every vertex, s^d through d mirror bounces: Le·(1 − s^(D+1))/(1 − s).
    CHECK(correctFurnaceValue(Lab::Uniform, mirror) == Approx(1.875));
    CHECK(correctFurnaceValue(Lab::Branching, {FurnaceWalls::Mirror, 0.5, 0, 0.8}) == Approx(1.0));
    CHECK(correctFurnaceValue(Lab::Roulette, mirror) == Approx(2.0).epsilon(1e-6));
    CHECK(furnaceFormula(Lab::Branching, mirror) ==
          "Le*(1 - s^(D+1))/(1 - s) with Le = 1, s = 0.5, D = 3");
    CHECK(furnaceFormula(Lab::Roulette, diffuse) == "Le/(1 - a) with Le = 1, a = 0.5");
}

TEST_CASE("the furnace models of the scenes in models/", "[grader]") {
    CHECK(furnaceModel("furnace", 3, 0.8)->walls == FurnaceWalls::Diffuse);
    CHECK(furnaceModel("furnace_a08", 5, 0.8)->reflectance == 0.8);
    CHECK(furnaceModel("mirror_furnace", 2, 0.5)->walls == FurnaceWalls::Mirror);
    CHECK(furnaceModel("mirror_furnace", 2, 0.5)->maxDepth == 2);
    // An inner sphere changes the depth-limited values: no model for those.
    CHECK_FALSE(furnaceModel("furnace_glass", 3, 0.8));
    CHECK_FALSE(furnaceModel("cornell_box_VI2_Specular", 3, 0.8));
}

TEST_CASE("the diffuse furnace names known bugs with the lab's step", "[grader]") {
    CHECK(likelyFurnaceCauses(Lab::Uniform, {{diffuse, 1.9375, 0.002}}, true).empty());
    // Forgetting the 1/3: each bounce weighs a/3, so 1.5 + 0.5/6 + 0.5/36 + 0.5/216.
    CHECK(contains(likeliest(Lab::Uniform, {{diffuse, 1.5995, 0.002}}),
                   "pick probability 1/3 (TODO lab2.4)"));
    // One bounce too many: the series runs to a^(maxDepth+2).
    CHECK(contains(likeliest(Lab::Branching, {{diffuse, 1.96875, 0.002}}), "one bounce too many"));
    CHECK(contains(likeliest(Lab::Importance, {{diffuse, 1.96875, 0.002}}), "TODO lab3.2"));
    // Emission after diffuse bounces too: Le once more at depths 1 to D, 0.875 more.
    CHECK(contains(likeliest(Lab::Importance, {{diffuse, 2.8125, 0.002}}),
                   "emission counted twice: it is added after diffuse bounces too, although "
                   "next-event estimation already counted it (TODO lab3.1)"));
    // Without the roulette weight each continuation weighs a·q = 0.4 instead of a: the camera
    // ray's Le plus next-event estimation's a at every vertex, 1 + 0.5/(1 − 0.4).
    CHECK(contains(likeliest(Lab::Roulette, {{diffuse, 1 + 0.5 / (1 - 0.4), 0.002}}),
                   "Russian-roulette weight missing"));
    // Divided by q twice: each continuation weighs a/q = 0.625, so 1 + 0.5/(1 − 0.625).
    CHECK(contains(likeliest(Lab::Roulette, {{diffuse, 1 + 0.5 / 0.375, 0.002}}),
                   "continueProb twice (TODO lab4.4)"));
    // pi·a > 1: the unbiased series diverges, and any huge or non-finite value fits it.
    CHECK(contains(likeliest(Lab::Roulette, {{diffuse, NAN, 0}}), "a factor of pi"));
}

TEST_CASE("the furnace at two maxDepths names a lab that ignores ctx.maxDepth", "[grader]") {
    const FurnaceModel deeper{FurnaceWalls::Diffuse, 0.5, 5, 0.8};
    // Right at maxDepth 3, and at maxDepth 5 the value of maxDepth 3 again: (1 - a^5)/(1 - a).
    const std::vector<FurnaceObservation> ignoring = {{diffuse, 1.9375, 0.0005},
                                                      {deeper, 1.9375, 0.0005}};
    CHECK(likeliest(Lab::Branching, ignoring) ==
          "ctx.maxDepth ignored: the lab renders as if maxDepth were 3, whatever ctx.maxDepth "
          "says (a constant in its place?) (TODO lab1.2)");
    CHECK(contains(likeliest(Lab::Importance, ignoring), "(TODO lab3.2)"));
    // A correct lab at both depths: nothing; one furnace alone cannot tell this cause.
    CHECK(likelyFurnaceCauses(Lab::Branching,
                              {{diffuse, 1.9375, 0.0005},
                               {deeper, correctFurnaceValue(Lab::Branching, deeper), 0.0005}},
                              true)
              .empty());
    for (const std::string& cause :
         likelyFurnaceCauses(Lab::Branching, {{diffuse, 1.9, 0.0005}}, true))
        CHECK_FALSE(contains(cause, "ctx.maxDepth ignored"));
    // Lab 4 has no depth limit to ignore.
    for (const std::string& cause : likelyFurnaceCauses(Lab::Roulette, ignoring, true))
        CHECK_FALSE(contains(cause, "ctx.maxDepth ignored"));
}

TEST_CASE("the mirror furnace names missing emission after specular bounces", "[grader]") {
    // Without emission after specular bounces a mirror-walled furnace shows the camera ray's Le
    // alone: no Kd, so next-event estimation adds nothing.
    for (Lab lab : AllLabs) {
        const std::string step = "(" + todoName(LabStep::Emission, lab) + ")";
        const std::string cause = likeliest(
            lab, {{diffuse, correctFurnaceValue(lab, diffuse), 0.002}, {mirror, 1.0, 0.0}});
        CHECK(contains(cause, "emission after a specular bounce missing"));
        CHECK(contains(cause, step));
    }
    // Alone, the mirror furnace cannot tell that bug from a lab without bounces, which also
    // shows Le; the diffuse furnace can (1 + a for the stub).
    const std::vector<std::string> alone =
        likelyFurnaceCauses(Lab::Branching, {{mirror, 1.0, 0.0}}, true);
    REQUIRE(alone.size() == 2);
    const std::string stub = likeliest(Lab::Branching, {{diffuse, 1.5, 0.002}, {mirror, 1.0, 0.0}});
    CHECK(contains(stub, "direct light only"));
    // A bug the mirror furnace cannot see is still found when it accepts the lab.
    CHECK(contains(likeliest(Lab::Branching, {{diffuse, 2.8125, 0.002}, {mirror, 1.875, 0.0}}),
                   "emission counted twice"));
    CHECK(likelyFurnaceCauses(Lab::Branching, {{mirror, 1.875, 0.0}}, true).empty());
}

TEST_CASE("NaN and refraction causes name the lab's step", "[grader]") {
    CHECK(contains(likelyNonfiniteCause(Lab::Importance), "near-black stop"));
    CHECK(contains(likelyNonfiniteCause(Lab::Importance), "(TODO lab3.3)"));
    CHECK(contains(likelyNonfiniteCause(Lab::Roulette), "(TODO lab4.3)"));
    // Labs 1 and 2 divide by no probability that can be zero: no step to name.
    CHECK_FALSE(contains(likelyNonfiniteCause(Lab::Branching), "TODO"));
    CHECK(contains(likelyRefractionCause(Lab::Branching), "(TODO lab1.5)"));
    // The diffuse direction: lab 1's diffuse bounce, the trace of the pick in labs 2-4.
    CHECK(contains(likelyDirectionCause(Lab::Branching), "(TODO lab1.3)"));
    CHECK(contains(likelyDirectionCause(Lab::Importance), "the pick's u again in diffuseRay's u"));
    CHECK(contains(likelyDirectionCause(Lab::Roulette), "(TODO lab4.4)"));
    CHECK(contains(likelyRefractionCause(Lab::Uniform), "(TODO lab2.4)"));
    CHECK(contains(likelyRefractionCause(Lab::Roulette), "(TODO lab4.3)"));
}

TEST_CASE("a lab 4 that kept lab 3's depth test is named", "[grader]") {
    // Roulette above a depth test is unbiased up to maxDepth: the depth-limited series, at the
    // rubric's maxDepth 3 and at the parameter check's 5: (1 - a^(D+2))/(1 - a).
    const FurnaceModel parameterCheck{FurnaceWalls::Diffuse, 0.5, 5, 0.5};
    const std::vector<FurnaceObservation> kept = {{diffuse, 1.9375, 0.002},
                                                  {parameterCheck, 1.984375, 0.002}};
    const std::string cause = likeliest(Lab::Roulette, kept);
    CHECK(contains(cause, "a depth limit is still there: lab 4 ends paths only by roulette"));
    CHECK(contains(cause, "(TODO lab4.2)"));
    // Labs 1-3 have a depth limit to keep: the same values are right for them.
    CHECK(likelyFurnaceCauses(Lab::Importance, kept, false).empty());
}

TEST_CASE("a lab whose steps are all written is told what it does, not what the stub did",
          "[grader]") {
    // Direct light only: 1 + a in the diffuse furnace, Le in the mirror furnace.
    const std::vector<FurnaceObservation> directOnly = {{diffuse, 1.5, 0.002}, {mirror, 1.0, 0.0}};
    const std::string stub = likeliest(Lab::Uniform, directOnly, true);
    CHECK(contains(stub, "still open"));
    const std::string written = likeliest(Lab::Uniform, directOnly, false);
    CHECK(contains(written, "direct light only, although no step is left open"));
    CHECK(contains(written, "1 / 3 divides integers"));
    CHECK_FALSE(contains(written, "still open"));
    CHECK(contains(written, "(from TODO lab2.3 on)"));
}

TEST_CASE("mixed_surfaces' channels off in opposite ways point to the pick, alike to the "
          "directions",
          "[grader]") {
    // A pick by luminance, a division by reduceMax: red too dark, blue too bright.
    CHECK(channelsOffOppositeWays({{0.80, 0.84}, {1.05, 1.09}, {1.20, 1.26}}));
    CHECK(channelsOffOppositeWays({{1.10, 1.14}, {0.97, 1.01}, {0.80, 0.86}}));
    // A diffuse direction from part of the hemisphere: every channel too dark, or too bright,
    // by different amounts.
    CHECK_FALSE(channelsOffOppositeWays({{0.70, 0.74}, {0.85, 0.89}, {0.90, 0.96}}));
    CHECK_FALSE(channelsOffOppositeWays({{1.20, 1.26}, {1.05, 1.09}, {0.98, 1.03}}));
    // A channel whose interval holds 1 is not off either way.
    CHECK_FALSE(channelsOffOppositeWays({{0.90, 1.02}, {1.05, 1.09}, {1.1, 1.2}}));
    CHECK(contains(likelyPickDivideCause(Lab::Importance),
                   "the probability you divide by must be the one you picked with"));
    CHECK(contains(likelyPickDivideCause(Lab::Importance), "(TODO lab3.4)"));
    CHECK(contains(likelyPickDivideCause(Lab::Uniform), "(TODO lab2.4)"));
    CHECK(contains(likelyPickDivideCause(Lab::Roulette), "(TODO lab4.4)"));
    CHECK(likelyPickDivideCause(Lab::Branching).empty());
}
