// The noise figure (pathlab/images/image_noise.h): its definition on samples whose statistics are
// known, and its one promise on the labs' scene, that it halves when the samples quadruple.
#include "catch.h"
#include "known_samples.h"
#include "test_support.h"

#include "runner/lab_tables.h"

#include "pathlab/render/scene_from_options.h"
#include "pathlab/render/accumulation_buffer.h"
#include "pathlab/images/image_noise.h"
#include "pathlab/support/pcg32.h"
#include "pathlab/render/renderer.h"

#include <cmath>

using namespace pathlab;

TEST_CASE("the noise figure is the RMS standard error of the pixels over the mean radiance",
          "[render][noise]") {
    // Two pixels, four samples each: pixel 0 sees 1, 3, 1, 3 in every channel (mean 2, sample
    // variance 4/3), pixel 1 sees 0s (a dark pixel: mean 0, variance 0).
    const AccumulationBuffer::Summary s = test::brightAndDarkPixel().summary();
    CHECK(s.meanRadiance.r == Approx(1.0));
    CHECK(s.meanVariance.g == Approx(2.0 / 3));
    // sqrt((4/3 + 0) / 2 / 4) / 1: the dark pixel adds its (zero) variance, and is never divided
    // by its own mean.
    CHECK(s.noise == Approx(std::sqrt(1.0 / 6)));
    CHECK(imageNoise(Color(2.0f / 3), Color(1.0f), 16) == Approx(std::sqrt(2.0 / 3 / 16)));
    CHECK(imageNoise(Color(1.0f), Color(0.0f), 16) == 0.0); // a black image
    CHECK(renderEfficiency(0.5, 2.0) == Approx(2.0));
}

TEST_CASE("the noise figure of rarely reached pixels halves when the samples quadruple",
          "[render][noise]") {
    // 10000 pixels that a path reaches rarely: each sample is 1 with probability p = 0.01, else 0
    // (a caustic seen through glass, say). Expected: sqrt(p(1-p)/N) / p, 1.244 at N = 64 and 0.622
    // at 256. Most pixels have no bright sample at 64 spp; a figure that leaves them out until
    // they are reached (the mean of per-pixel relative errors did) falls far more slowly. With
    // 10000 pixels the figure's own spread is under 1%: 5% is over 5 of it (fixed seed).
    const double p = 0.01;
    Pcg32 random(42, 7);
    for (int spp : {64, 256}) {
        AccumulationBuffer buffer(10000, 1);
        for (int s = 0; s < spp; ++s)
            for (int pixel = 0; pixel < 10000; ++pixel)
                buffer.addSample(pixel, Color(random.nextFloat() < p ? 1.0f : 0.0f));
        buffer.finishPass(spp);
        INFO(spp << " spp");
        CHECK(buffer.summary().noise == Approx(std::sqrt(p * (1 - p) / spp) / p).epsilon(0.05));
    }
}

namespace {

/// The noise figure of one progressive render of a lab's solution on the VI2 box at `size`²,
/// read after each of `spps` samples per pixel, as the window's panel reads it frame after frame.
std::vector<double> progressiveNoise(const char* lab, const char* continueProb, int size,
                                     std::vector<int> spps, uint64_t seed) {
    const std::string scene = test::modelPath("cornell_box_VI2_Specular.ecs"),
                      side = std::to_string(size);
    const char* argv[] = {"viewer",          "-c",         scene.c_str(), "--size",
                          side.c_str(),      side.c_str(), "--lab",       lab,
                          "--continue-prob", continueProb, "--solution"};
    const RenderOptions options = parseRenderOptions(11, argv);
    const RenderScene renderScene(loadScene(options));
    const Camera camera(*renderScene.scene().camera, size, size);
    Renderer renderer(renderScene, 0);
    AccumulationBuffer buffer(size, size);
    std::vector<double> noise;
    for (int spp : spps) {
        renderer.renderPass(buffer, camera, findPathTrace(options.lab, Implementation::Solution),
                            options.parameters, seed, spp - buffer.samplesPerPixel());
        noise.push_back(buffer.summary().noise);
    }
    return noise;
}

} // namespace

// For an estimator of finite variance, noise(N) / noise(4N) = 2 in expectation. How close one
// render comes depends on the estimator's tails and the number of pixel samples: over 25 seeds
// of progressive renders at 128x128, the uniform pick (the lab with the heaviest tail) gave
// 64 -> 256 ratios with a standard deviation of 0.082 and 256 -> 1024 ratios with 0.042; the
// other labs spread less. So 64 -> 256 is checked at 256x256 (4 times the pixels: about 0.041)
// and 256 -> 1024 at 128x128, each within 10%: about 5 standard deviations, so that were the
// ratios normal, a false failure would have a chance below 1e-5 per check (the seeds are fixed:
// the outcome is reproducible). Roulette is checked at
// continueProb 0.8; at 0.1 its variance is infinite on this scene and the figure is not expected
// to halve (handout 4's first question).
TEST_CASE("the noise figure halves when the samples quadruple, 64 -> 256 -> 1024 spp",
          "[render][noise][solutions]") {
    struct Case {
        const char* lab;
        const char* continueProb;
    };
    for (const Case c : {Case{"branching", "0.1"}, Case{"uniform", "0.1"},
                         Case{"importance", "0.1"}, Case{"roulette", "0.8"}}) {
        const std::vector<double> large =
            progressiveNoise(c.lab, c.continueProb, 256, {64, 256}, 21);
        const std::vector<double> small =
            progressiveNoise(c.lab, c.continueProb, 128, {256, 1024}, 22);
        INFO(c.lab << " at continueProb " << c.continueProb << ": noise " << large[0] << " -> "
                   << large[1] << " from 64 to 256 spp at 256x256, " << small[0] << " -> "
                   << small[1] << " from 256 to 1024 spp at 128x128");
        CHECK(large[0] / large[1] == Approx(2.0).epsilon(0.1));
        CHECK(small[0] / small[1] == Approx(2.0).epsilon(0.1));
    }
}
