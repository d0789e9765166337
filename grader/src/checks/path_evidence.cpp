#include "checks/path_evidence.h"

#include "checks/hypothesis_tests.h"
#include "checks/number_text.h"

#include <algorithm>
#include <cmath>

namespace pathlab::grader {

namespace {

// The margins. A correct lab's variance is of the order of the reference's (the noise check
// allows 1.5 times it; the labs differ by up to ten times between them), its bounce rays too
// (0.56 to 3.6 per sample on the VI2 box), and its detail slope near 1: each limit below is
// far beyond what sampling noise or a valid variant of the estimator makes.
constexpr double VarianceShare = 0.01;   ///< of the reference's per-sample variance
constexpr double BounceShare = 0.1;      ///< of the reference's bounce rays per sample
constexpr double LeastBounceRays = 0.05; ///< below this the reference traces too few to tell
constexpr double DetailShare = 0.5;      ///< of the reference's detail inside the tiles
/// The reference's detail must stand this far above what its own noise would make.
constexpr double DetailOverNoise = 20;

/// Each pixel less its tile's mean, channel by channel.
std::vector<double> insideTiles(const std::vector<float>& image, int width, int height, int tiles) {
    std::vector<double> sums(3 * static_cast<size_t>(tiles) * tiles, 0.0);
    std::vector<double> counts(static_cast<size_t>(tiles) * tiles, 0.0);
    auto tileOf = [&](int x, int y) {
        return static_cast<size_t>((y * tiles / height) * tiles + (x * tiles / width));
    };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t t = tileOf(x, y), p = 3 * (static_cast<size_t>(y) * width + x);
            counts[t] += 1;
            for (size_t c = 0; c < 3; ++c) sums[3 * t + c] += image[p + c];
        }
    std::vector<double> deviations(image.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t t = tileOf(x, y), p = 3 * (static_cast<size_t>(y) * width + x);
            for (size_t c = 0; c < 3; ++c)
                deviations[p + c] = image[p + c] - sums[3 * t + c] / counts[t];
        }
    return deviations;
}

} // namespace

double detailInsideTiles(const PathEvidence& e) {
    const size_t values = 3 * static_cast<size_t>(e.width) * e.height;
    if (e.meanImage.size() != values || e.referenceImage.size() != values) return -1;
    const std::vector<double> lab = insideTiles(e.meanImage, e.width, e.height, e.tiles);
    const std::vector<double> reference = insideTiles(e.referenceImage, e.width, e.height, e.tiles);
    double product = 0, square = 0, level = 0;
    for (size_t i = 0; i < values; ++i) {
        product += lab[i] * reference[i];
        square += reference[i] * reference[i];
        level += std::fabs(e.referenceImage[i]) / static_cast<double>(values);
    }
    // What the reference's own noise alone would put there, about its variance per value, or
    // float rounding where it has none (the mirror furnace, the same for every path).
    const double rounding = floatRoundingFloor * level;
    const double noise = std::max(e.referenceNoise, rounding * rounding);
    if (!(square > DetailOverNoise * noise * static_cast<double>(values))) return -1;
    return product / square;
}

std::string missingPathEvidence(const PathEvidence& e) {
    if (e.referenceVariance > 0 && e.variance < VarianceShare * e.referenceVariance)
        return "its pixels do not vary from seed to seed (per-sample variance " +
               significant(e.variance, 3) + ", where the quietest reference solution's is " +
               significant(e.referenceVariance, 3) +
               "): an image computed without random paths, not an estimate";
    if (e.referenceBounceRays >= LeastBounceRays &&
        e.bounceRays < BounceShare * e.referenceBounceRays)
        return "it traces " + fixed(e.bounceRays, 2) +
               " bounce rays per sample, where every lab's estimator traces at least " +
               fixed(e.referenceBounceRays, 2) + ": its light is not gathered along paths";
    const double detail = detailInsideTiles(e);
    if (detail >= 0 && detail < DetailShare)
        return "inside each of the tiles the grader compares, its image has " + fixed(detail, 2) +
               " of the detail the reference image has: flat where it should show the scene, as "
               "a table of tile means would be";
    return "";
}

} // namespace pathlab::grader
