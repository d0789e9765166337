// No lab may give a pixel a NaN or infinite sample: one such sample spoils the pixel's mean for
// good. The scenes the grader renders hold a material with no component at all (Ke only: the
// VI2 box's light and refraction_check's glowing wall), on which a pick by importance without
// the near-black stop divides 0 by 0 (steps lab3.3, lab4.3).
//
// Deterministic for a given seed, with no statistics: a correct lab never fails it. Lab 4 runs at
// the graded continueProb 0.8, so its paths are long enough to meet every surface.
#include "catch.h"
#include "lab_checks.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

void checkFiniteOnGradedScenes(Lab lab) {
    const std::vector<std::string> options =
        isDepthLimited(lab) ? std::vector<std::string>{}
                            : std::vector<std::string>{"--continue-prob", "0.8"};
    for (const char* scene : {"cornell_box_VI2_Specular.ecs", "refraction_check.ecs"})
        checkFinite(renderLab(lab, scene, 64, 8, 1, options));
}

} // namespace

TEST_CASE("lab 1 branching: no NaN or infinite sample", "[lab1]") {
    checkFiniteOnGradedScenes(Lab::Branching);
}

TEST_CASE("lab 2 uniform pick: no NaN or infinite sample", "[lab2]") {
    checkFiniteOnGradedScenes(Lab::Uniform);
}

TEST_CASE("lab 3 importance pick: no NaN or infinite sample", "[lab3]") {
    checkFiniteOnGradedScenes(Lab::Importance);
}

TEST_CASE("lab 4 Russian roulette: no NaN or infinite sample", "[lab4]") {
    checkFiniteOnGradedScenes(Lab::Roulette);
}
