// The reference solutions of labs 1-3 estimate the same depth-limited image, so on the VI2
// Cornell box (mirror, glass, coloured walls, area light) their means must agree. The lab tests
// compare each lab with the grader's stored reference, which the importance solution measured
// (reference_agreement_test.cpp); this is the independent check that the branching and uniform
// solutions see the same image. Kit only: the student release has no solutions.
//
// For each pair, a Welch test per channel of the difference of the image means, each mean's
// standard error from its per-pixel sample variances (its degrees of freedom are in the tens of
// thousands, so the normal critical value is used). Significance alpha = 1e-4 per comparison;
// 3 pairs × 3 channels, family-wise false-fail rate below 1e-3. Fixed seeds make the outcome
// reproducible.
#include "catch.h"
#include "statistics.h"
#include "test_support.h"

#include <cmath>

using namespace pathlab;

TEST_CASE("the solutions of labs 1-3 agree on the VI2 Cornell box (Welch test, alpha 1e-4 each)",
          "[solutions][agreement]") {
    const Lab labs[] = {Lab::Branching, Lab::Uniform, Lab::Importance};
    test::Estimate estimates[3];
    for (int i = 0; i < 3; ++i) {
        // Independent seeds per lab, so the test compares independent estimates.
        estimates[i] = test::estimateOf(
            test::render({"-c", test::modelPath("cornell_box_VI2_Specular.ecs"), "--size", "64",
                          "64", "--spp", i == 0 ? "16" : "64", "--seed", std::to_string(100 + i),
                          "--lab", std::string(labName(labs[i])), "--solution"}));
    }
    const double critical = test::normalCritical(1e-4);
    for (int i = 0; i < 3; ++i) {
        for (int j = i + 1; j < 3; ++j) {
            for (int c = 0; c < 3; ++c) {
                const double difference = estimates[i].mean[c] - estimates[j].mean[c];
                const double se =
                    std::hypot(estimates[i].standardError[c], estimates[j].standardError[c]);
                INFO(labName(labs[i]) << " vs " << labName(labs[j]) << " channel " << c << ": "
                                      << estimates[i].mean[c] << " vs " << estimates[j].mean[c]
                                      << ", Welch z " << difference / se);
                CHECK(std::fabs(difference / se) < critical);
            }
        }
    }
}
