// Each lab's image of the VI2 Cornell box (mirror, glass, coloured walls, area light) against
// the grader's stored reference, grader/references/cornell_box_VI2_Specular.json: the mean of
// 40 seeds' images rendered by the solutions (`grader make-references`; region 0 is the whole
// image, per channel, with the standard error of the 40 seeds' batch mean). Labs 1-3 are
// compared with its depth-limited expectation at its maxDepth, lab 4 with its unbiased one at
// its continueProb, at the reference's size.
//
// Per channel a two-sided z-test of the difference (lab_checks.h), alpha 1e-5: a correct lab
// fails with probability at most 3e-5 (3 channels), and with fixed seeds (not the reference's)
// the outcome is reproducible. The render's standard error comes from ~10^5 samples' per-pixel
// variances; the reference's, 5 to 10 times smaller, is itself an estimate from 40 seeds
// (39 degrees of freedom, so within ±25% at 95%): with its share of the combined variance
// under 2%, that uncertainty moves the test's size by well under a tenth. Over 300 seeds of labs
// 1, 3 and 4 (900 channel tests each) the solutions' z had an rms of 0.95 to 1.0 and stayed
// within 3.3. Lab 2's fireflies give its z a heavier lower tail: at 128 spp, 16 of 4,500 values
// beyond 3 (a normal gives 12) and one of 900 at 4.05; at the 256 spp used here, 6 of 900 beyond
// 3 (normal: 2.4) and none beyond 3.6. Its false-fail rate is estimated below 1e-3.
#include "catch.h"
#include "lab_checks.h"
#include "test_support.h"

#include "checks/expectation.h"
#include "checks/rubric.h"

using namespace pathlab;
using namespace pathlab::test;

namespace {

const grader::SceneReference& vi2Reference() {
    static const grader::SceneReference reference = grader::loadReference(
        PATHLAB_GRADER_DIR "/references", pathlab::test::modelPath("cornell_box_VI2_Specular.ecs"),
        grader::loadRubric(PATHLAB_GRADER_DIR "/rubric.json"));
    return reference;
}

/// The lab at `spp` (chosen for a standard error near 0.5% of the mean in a fraction of a
/// second) against the reference.
void checkAgainstVi2Reference(Lab lab, int spp) {
    const grader::SceneReference& reference = vi2Reference();
    REQUIRE(reference.width == reference.height);
    const LabRun run = renderLab(lab, "cornell_box_VI2_Specular.ecs", reference.width, spp, 7,
                                 {"--max-depth", std::to_string(reference.maxDepth),
                                  "--continue-prob", std::to_string(reference.continueProb)});
    checkAgainstReference(run, reference.forLab(lab));
}

} // namespace

TEST_CASE("lab 1 branching: the VI2 box's mean is the stored reference's", "[lab1]") {
    checkAgainstVi2Reference(Lab::Branching, 32);
}

TEST_CASE("lab 2 uniform pick: the VI2 box's mean is the stored reference's", "[lab2]") {
    checkAgainstVi2Reference(Lab::Uniform, 256);
}

TEST_CASE("lab 3 importance pick: the VI2 box's mean is the stored reference's", "[lab3]") {
    checkAgainstVi2Reference(Lab::Importance, 64);
}

TEST_CASE("lab 4 Russian roulette: the VI2 box's mean is the stored reference's", "[lab4]") {
    checkAgainstVi2Reference(Lab::Roulette, 64);
}
