// Russian roulette's path lengths in a diffuse furnace: q/(1-q) bounce rays per sample, and the
// verdicts on labs whose paths do not follow ctx.continueProb.
#include "catch.h"
#include "messages.h"

#include "checks/path_length.h"

using namespace pathlab::grader;

TEST_CASE("roulette traces q/(1-q) bounce rays per sample in a closed furnace", "[grader]") {
    // P(k bounces) = q^k (1 - q): the mean of a geometric count.
    CHECK(expectedBounceRays(0.8) == Approx(4.0));
    CHECK(expectedBounceRays(0.5) == Approx(1.0));
    CHECK(expectedBounceRays(0.1) == Approx(1.0 / 9));
}

TEST_CASE("paths as long at both continueProbs: the lab ignores ctx.continueProb", "[grader]") {
    // The handout's example constant, 0.1: 1/9 bounce rays per sample whatever the rubric says.
    const std::string cause = ignoredContinueProb({{0.8, 0.111}, {0.5, 0.112}});
    CHECK(contains(cause, "ctx.continueProb ignored: the paths are as long at one continueProb "
                          "as at the other"));
    CHECK(contains(cause, "0.11 at continueProb 0.8, 0.11 at continueProb 0.5"));
    CHECK(contains(cause, "gives 4.00 at continueProb 0.8, 1.00 at continueProb 0.5"));
    CHECK(contains(cause, "(TODO lab4.2)"));
    // A constant that happens to be the rubric's still ignores the second value.
    CHECK_FALSE(ignoredContinueProb({{0.8, 4.0}, {0.5, 4.0}}).empty());
}

TEST_CASE("a lab that follows ctx.continueProb is neither failed nor noted", "[grader]") {
    const std::vector<PathLengthObservation> correct = {{0.8, 4.006}, {0.5, 0.998}};
    CHECK(ignoredContinueProb(correct).empty());
    CHECK(pathLengthNote(correct).empty());
    // One continueProb alone cannot show that the lab ignores it.
    CHECK(ignoredContinueProb({{0.8, 0.11}}).empty());
    // No bounce at all (the stub): a missing bounce, which the furnaces' values name.
    CHECK(ignoredContinueProb({{0.8, 0.0}, {0.5, 0.0}}).empty());
}

TEST_CASE("paths that lengthen with continueProb, but not as lab 4 asks, get a note", "[grader]") {
    // One bounce before roulette starts: 1 + q/(1-q). Unbiased, and not the handout's estimator.
    const std::vector<PathLengthObservation> forcedBounce = {{0.8, 5.0}, {0.5, 2.0}};
    CHECK(ignoredContinueProb(forcedBounce).empty());
    CHECK(contains(pathLengthNote(forcedBounce), "do not follow continueProb as lab 4 specifies"));
}
