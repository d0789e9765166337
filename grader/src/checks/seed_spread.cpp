#include "checks/seed_spread.h"

#include "checks/hypothesis_tests.h"

#include <algorithm>
#include <cmath>

namespace pathlab::grader {

namespace {

/// The pixels' sums of channels in [x0, x1) × [y0, y1), per seed: the variance of their mean
/// over the seeds, and the sum of their own variances over N² (independent pixels).
struct RegionVariances {
    double ofMean = 0, independent = 0, mean = 0;
};

RegionVariances regionVariances(const std::vector<std::vector<float>>& images, int width, int x0,
                                int x1, int y0, int y1) {
    const size_t seeds = images.size();
    const double pixels = double(x1 - x0) * (y1 - y0);
    std::vector<double> means(seeds, 0.0);
    double pixelVariances = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const size_t at = 3 * (size_t(y) * width + x);
            double sum = 0, squares = 0;
            for (size_t s = 0; s < seeds; ++s) {
                const double v = double(images[s][at]) + images[s][at + 1] + images[s][at + 2];
                means[s] += v / pixels;
                sum += v, squares += v * v;
            }
            pixelVariances += std::max(0.0, (squares - sum * sum / seeds) / (seeds - 1));
        }
    RegionVariances r;
    double sum = 0, squares = 0;
    for (double m : means) sum += m, squares += m * m;
    r.mean = sum / seeds;
    r.ofMean = std::max(0.0, (squares - sum * sum / seeds) / (seeds - 1));
    r.independent = pixelVariances / (pixels * pixels);
    return r;
}

double correlation(const RegionVariances& r) {
    return r.independent > 0 ? r.ofMean / r.independent : 0;
}

} // namespace

SeedSpread seedSpread(const std::vector<std::vector<float>>& images, int width, int height,
                      int tiles) {
    SeedSpread spread;
    if (images.size() < 2 || width < 1 || height < 1 || tiles < 1) return spread;
    const RegionVariances whole = regionVariances(images, width, 0, width, 0, height);
    spread.wholeImageCorrelation = correlation(whole);
    if (whole.mean != 0)
        spread.relativeStandardError =
            std::sqrt(whole.ofMean / images.size()) / std::fabs(whole.mean);
    std::vector<double> byTile;
    for (int ty = 0; ty < tiles; ++ty)
        for (int tx = 0; tx < tiles; ++tx)
            byTile.push_back(correlation(
                regionVariances(images, width, tx * width / tiles, (tx + 1) * width / tiles,
                                ty * height / tiles, (ty + 1) * height / tiles)));
    spread.medianTileCorrelation = median(byTile);
    return spread;
}

bool tooNoisyToJudge(const SeedSpread& spread) {
    return spread.wholeImageCorrelation > MaxCorrelation ||
           spread.medianTileCorrelation > MaxCorrelation ||
           spread.relativeStandardError > MaxRelativeStandardError;
}

} // namespace pathlab::grader
