// Error against a reference (pathlab/images/relative_mse.h, relative_error_map.h) and the per-pixel
// noise and efficiency maps (pixel_noise_map.h, pixel_efficiency_map.h), against values computed
// here by hand from their definitions; and the log scale the maps' PNGs are coloured on.
#include "catch.h"
#include "known_samples.h"
#include "test_support.h"

#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/images/false_colour.h"
#include "pathlab/images/pixel_efficiency_map.h"
#include "pathlab/images/pixel_noise_map.h"
#include "pathlab/images/relative_error_map.h"
#include "pathlab/images/relative_mse.h"
#include "pathlab/images/scale_bar.h"

#include <cmath>

using namespace pathlab;

namespace {

/// A render of the VI2 box by lab 3's reference solution, small and with a fixed seed.
std::vector<float> smallRender() {
    return test::render({"-c", test::modelPath("cornell_box_VI2_Specular.ecs"), "--size", "32",
                         "24", "--spp", "4", "--seed", "3", "--lab", "importance", "--solution"})
        .image.meanImage();
}

} // namespace

TEST_CASE("relMSE of a render against itself is 0, against a half-bright copy known",
          "[render][reference][solutions]") {
    const std::vector<float> reference = smallRender();
    CHECK(relativeMse(reference, reference) == 0.0);
    CHECK(relativeRmse(reference, reference) == 0.0);

    std::vector<float> half(reference.size());
    for (size_t i = 0; i < half.size(); ++i) half[i] = reference[i] / 2;
    // x = r/2: (r/2)² / (r² + ε) per value, ε = 0.01; and sqrt(mean (r/2)²) / mean r.
    double expectedMse = 0, squares = 0, sum = 0;
    for (float r : reference) {
        expectedMse += (r / 2.0) * (r / 2.0) / (static_cast<double>(r) * r + 0.01);
        squares += (r / 2.0) * (r / 2.0);
        sum += r;
    }
    const double n = static_cast<double>(reference.size());
    expectedMse /= n;
    REQUIRE(expectedMse > 0.05); // the box is lit: the figure is far from 0
    CHECK(relMseEpsilon == 0.01);
    CHECK(relativeMse(half, reference) == Approx(expectedMse).epsilon(1e-9));
    CHECK(relativeRmse(half, reference) == Approx(std::sqrt(squares / n) / (sum / n)));

    // The per-pixel map averages the channels, and its mean over the pixels is relMSE.
    const std::vector<float> map = relativeErrorMap(half, reference);
    REQUIRE(map.size() == reference.size() / 3);
    double mapSum = 0;
    for (float v : map) mapSum += v;
    CHECK(mapSum / static_cast<double>(map.size()) == Approx(expectedMse).epsilon(1e-6));
    const float r0 = reference[0], r1 = reference[1], r2 = reference[2];
    CHECK(map[0] == Approx(((r0 * r0 / 4) / (r0 * r0 + 0.01) + (r1 * r1 / 4) / (r1 * r1 + 0.01) +
                            (r2 * r2 / 4) / (r2 * r2 + 0.01)) /
                           3));
}

TEST_CASE("the noise map is each pixel's relative standard error, the efficiency map "
          "1 / (relative variance x seconds per sample)",
          "[render][reference]") {
    // Pixel 0 sees 1, 3, 1, 3 in every channel (mean 2, sample variance 4/3); pixel 1 sees 0s.
    const AccumulationBuffer buffer = test::brightAndDarkPixel();
    std::vector<float> mean, variance;
    buffer.meanImage(mean);
    buffer.varianceImage(variance);
    CHECK(variance[0] == Approx(4.0 / 3));
    const std::vector<float> noise = relativeStandardErrorMap(mean, variance, 4);
    REQUIRE(noise.size() == 2);
    const double expected = std::sqrt((4.0 / 3) / 4 / (2.0 * 2.0 + 0.01));
    CHECK(noise[0] == Approx(expected));
    CHECK(noise[1] == 0.0f); // no noise: nothing to divide by
    CHECK(relativeStandardErrorMap(mean, variance, 1)[0] == 0.0f);

    // 2 seconds for 4 spp: per sample relative variance (4/3)/(4.01), 0.5 s per sample.
    const std::vector<float> efficiency = efficiencyMap(noise, 2.0);
    CHECK(efficiency[0] == Approx(1.0 / ((4.0 / 3) / 4.01 * 0.5)));
    CHECK(efficiency[1] == 0.0f); // undefined
    CHECK(efficiencyMap(noise, 0.0)[0] == 0.0f);
}

TEST_CASE("the maps' log scale spans whole decades around the values", "[render][reference]") {
    std::vector<float> values;
    for (int i = 1; i <= 100; ++i) values.push_back(0.02f * static_cast<float>(i)); // 0.02 .. 2
    values.push_back(0.0f); // undefined: not part of the scale
    const LogScale scale = decadeScale(values);
    CHECK(scale.low == Approx(0.01f));
    CHECK(scale.high == Approx(10.0f));
    CHECK(scale.position(0.1f) == Approx(1.0 / 3));
    CHECK(scale.position(1e-6f) == 0.0f);
    CHECK(scale.position(1e6f) == 1.0f);
    const LogScale flat = decadeScale(std::vector<float>(10, 1.0f));
    CHECK(flat.low == Approx(1.0f));
    CHECK(flat.high == Approx(10.0f));
    CHECK(scaleLabel(0.01f) == "0.01");
    CHECK(scaleLabel(1000.0f) == "1000");
    CHECK(scaleLabel(1e-5f) == "1e-5");

    std::vector<unsigned char> rgba;
    logScaleImage({0.0f, 0.01f, 10.0f}, scale, rgba);
    CHECK((rgba[0] == undefinedGrey && rgba[1] == undefinedGrey && rgba[2] == undefinedGrey));
    CHECK((rgba[4] == 0 && rgba[5] == 0 && rgba[6] == 0));    // low end: black
    CHECK((rgba[8] == 255 && rgba[9] == 0 && rgba[10] == 0)); // high end: red
    const std::vector<unsigned char> withBar = withScaleBarBelow(rgba, 3, 1, scale);
    CHECK(withBar.size() == 3u * 3 * (1 + static_cast<size_t>(scaleBarHeight(3))));
}
