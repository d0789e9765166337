// Whether a lab's images come from tracing paths (checks/path_evidence.h), on the shipped
// reference images of the VI2 box and the furnace: a rendered image has the detail inside the
// tiles that the reference has (about 1 of it), a table of the tiles' means none (0); a furnace
// has no detail to judge by. Noise of a correct lab's size is added with a fixed seed.
#include "catch.h"

#include "checks/path_evidence.h"

#include "pathlab/images/image_io.h"

#include <random>
#include <string>

using namespace pathlab;
using namespace pathlab::grader;

namespace {

std::vector<float> referenceImage(const std::string& scene) {
    return readImage(std::string(PATHLAB_GRADER_DIR) + "/references/" + scene +
                     ".depth_limited.exr")
        .rgb;
}

/// `image` with each of its tiles (4x4 of a 64x64 image) replaced by the tile's mean.
std::vector<float> tileMeans(const std::vector<float>& image) {
    std::vector<double> sums(16 * 3, 0.0);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                sums[3 * ((y / 16) * 4 + x / 16) + c] += image[3 * (y * 64 + x) + c] / 256.0;
    std::vector<float> flat(image.size());
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                flat[3 * (y * 64 + x) + c] =
                    static_cast<float>(sums[3 * ((y / 16) * 4 + x / 16) + c]);
    return flat;
}

/// `image` with noise of relative standard deviation `relative` added, from a fixed seed.
std::vector<float> noisy(std::vector<float> image, double relative) {
    std::mt19937 engine(7);
    std::normal_distribution<double> normal(0, relative);
    for (float& v : image) v = static_cast<float>(v * (1 + normal(engine)));
    return image;
}

PathEvidence evidence(const std::vector<float>& lab, const std::vector<float>& reference) {
    PathEvidence e;
    e.meanImage = lab;
    e.referenceImage = reference;
    e.width = e.height = 64;
    e.tiles = 4;
    // The VI2 reference's own noise: importance's per-sample variance over 128 spp x 40 seeds.
    e.referenceNoise = 0.118 / (128 * 40);
    e.variance = e.referenceVariance = 0.09;
    e.bounceRays = e.referenceBounceRays = 3.6;
    return e;
}

} // namespace

TEST_CASE("a rendered image has the reference's detail inside the tiles, a table of tile means "
          "none",
          "[grader]") {
    const std::vector<float> box = referenceImage("cornell_box_VI2_Specular");
    // A correct lab's mean image over 10 seeds of 8 spp: about 10% noise per pixel (and more).
    CHECK(detailInsideTiles(evidence(noisy(box, 0.1), box)) == Approx(1).margin(0.05));
    CHECK(detailInsideTiles(evidence(noisy(box, 0.5), box)) == Approx(1).margin(0.1));
    CHECK(missingPathEvidence(evidence(noisy(box, 0.1), box)).empty());
    // The tile means with noise (so that its pixels vary), and a table without.
    CHECK(detailInsideTiles(evidence(noisy(tileMeans(box), 0.1), box)) == Approx(0).margin(0.05));
    const std::string flat = missingPathEvidence(evidence(noisy(tileMeans(box), 0.3), box));
    CHECK(flat.find("inside each of the tiles the grader compares, its image has 0.0") == 0);
}

TEST_CASE("a furnace has no detail inside its tiles to judge a lab by", "[grader]") {
    const std::vector<float> furnace = referenceImage("furnace");
    PathEvidence e = evidence(furnace, furnace);
    e.referenceNoise = 0.0036 / (128 * 40);
    CHECK(detailInsideTiles(e) == -1);
    e.meanImage = tileMeans(furnace);
    CHECK(missingPathEvidence(e).empty());
}

TEST_CASE("pixels that do not vary, and no bounce rays, where the reference's do", "[grader]") {
    const std::vector<float> box = referenceImage("cornell_box_VI2_Specular");
    PathEvidence e = evidence(box, box);
    e.variance = 0;
    CHECK(missingPathEvidence(e).find(
              "its pixels do not vary from seed to seed (per-sample "
              "variance 0, where the quietest reference solution's is 0.09)") == 0);
    e.variance = 0.2 * e.referenceVariance; // a lower-variance estimator is no table
    CHECK(missingPathEvidence(e).empty());
    e.referenceVariance = 0; // the mirror furnace: a deterministic reference says nothing
    e.variance = 0;
    CHECK(missingPathEvidence(e).empty());
    e.bounceRays = 0;
    CHECK(missingPathEvidence(e).find("it traces 0.00 bounce rays per sample, where every lab's "
                                      "estimator traces at least 3.60") == 0);
    e.bounceRays = 0.56; // lab 2 traces a sixth of lab 1's: no table
    CHECK(missingPathEvidence(e).empty());
    e.referenceBounceRays = -1; // a reference made before the counts were kept
    e.bounceRays = 0;
    CHECK(missingPathEvidence(e).empty());
}
