// Every lab in the mirror furnace (models/mirror_furnace.ecs): a closed sphere whose walls are a
// perfect mirror of reflectance s = 0.5 (Ks, no Kd, no Kt) and emit Le = 1, the camera inside.
//
// Every path meets only mirror reflections, and next-event estimation finds nothing (it lights
// Kd only): all the light beyond what the camera ray sees comes from the emission added after
// specular bounces (step labN.1). A hit at depth d, reached through d mirror bounces, adds
// s^d·Le, so with the depth limit D the radiance is Le·(1 − s^(D+1))/(1 − s) (1.875 at D = 3),
// with Russian roulette Le/(1 − s) = 2, and a lab that adds emission for camera rays only gives
// exactly Le = 1. (Labs 1 and 3 have no randomness left here: every sample is the value.)
//
// False fails: each render is one check at alpha 1e-5 (lab_checks.h); a correct lab fails none
// of its two with probability at least 1 − 2e-5. Over 300 seeds of each check the solutions'
// largest |z| was 3.1.
#include "catch.h"
#include "lab_checks.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

/// The mirror furnace at the default depth limit and another, or at two continueProbs.
void checkMirrorFurnace(Lab lab) {
    const char* option = isDepthLimited(lab) ? "--max-depth" : "--continue-prob";
    for (const char* value : isDepthLimited(lab) ? std::vector<const char*>{"3", "5"}
                                                 : std::vector<const char*>{"0.8", "0.5"})
        checkFurnace(renderLab(lab, "mirror_furnace.ecs", 48, 32, 1, {option, value}));
}

} // namespace

TEST_CASE("lab 1 branching: the mirror furnace sees emission after specular bounces", "[lab1]") {
    checkMirrorFurnace(Lab::Branching);
}

TEST_CASE("lab 2 uniform pick: the mirror furnace sees emission after specular bounces", "[lab2]") {
    checkMirrorFurnace(Lab::Uniform);
}

TEST_CASE("lab 3 importance pick: the mirror furnace sees emission after specular bounces",
          "[lab3]") {
    checkMirrorFurnace(Lab::Importance);
}

TEST_CASE("lab 4 Russian roulette: the mirror furnace sees emission after specular bounces",
          "[lab4]") {
    checkMirrorFurnace(Lab::Roulette);
}
