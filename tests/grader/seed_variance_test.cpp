// The noise check's trimmed per-sample variance on images whose per-pixel spread is known.
#include "catch.h"

#include "checks/seed_variance.h"

#include <vector>

using namespace pathlab::grader;

namespace {

/// k images of `pixels` pixels; pixel p of image i has the value values[i] in every channel.
std::vector<std::vector<float>> images(const std::vector<float>& values, int pixels) {
    std::vector<std::vector<float>> result;
    for (float v : values) result.push_back(std::vector<float>(3 * pixels, v));
    return result;
}

} // namespace

TEST_CASE("the trimmed per-sample variance is the spread of the seeds' pixel means times spp",
          "[grader]") {
    // Values 1, 2, 3, 4: sample variance 5/3; at 8 spp a sample's variance is 8·5/3.
    CHECK(trimmedSampleVariance(images({1, 2, 3, 4}, 500), 8) == Approx(8 * 5.0 / 3));
    CHECK(trimmedSampleVariance(images({2, 2, 2}, 100), 16) == Approx(0.0));
}

TEST_CASE("the trimmed per-sample variance leaves out the noisiest 1% of pixels", "[grader]") {
    // 1000 pixels with spread 5/3 at 1 spp, and 10 pixels (1%) with a firefly in one seed.
    auto seeds = images({1, 2, 3, 4}, 1010);
    for (int p = 1000; p < 1010; ++p)
        for (int c = 0; c < 3; ++c) seeds[0][3 * p + c] = 1e6f;
    CHECK(trimmedSampleVariance(seeds, 1) == Approx(5.0 / 3).epsilon(1e-6));
    // One more firefly than the share left out raises it, as it should.
    for (int c = 0; c < 3; ++c) seeds[0][3 * 999 + c] = 1e6f;
    CHECK(trimmedSampleVariance(seeds, 1) > 100);
}
