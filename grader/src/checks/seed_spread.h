#pragma once
/// Whether a lab's comparison with the reference could have found a difference. A t-test is
/// only as strong as its standard error: a lab that adds to each seed's image a value that
/// changes with the seed (the whole image, or a tile at a time), or returns rare enormous
/// samples, makes every region's standard error so large that no difference is significant, and
/// a stub would match. Such a lab is too noisy to judge, and is not taken as matching.
///
/// Two measures, neither needing the reference's noise (each lab's estimator has its own):
/// - correlation: a path tracer's pixels are independent (each has its own samples), so the
///   variance of a region's mean from seed to seed is the sum of its pixels' variances over N².
///   A value added to many pixels at once makes it up to N times that.
/// - size: the whole image's mean is known to a few parts in a thousand at the rubric's samples
///   for every lab; one whose standard error is a tenth of the mean cannot be told from a stub.

#include <vector>

namespace pathlab::grader {

struct SeedSpread {
    /// The variance of the region means over the seeds, over what independent pixels give: the
    /// whole image's, and the median over the tiles' (a few tiles do not decide it). About 1 for
    /// a path tracer; 0 where the region has no noise.
    double wholeImageCorrelation = 0, medianTileCorrelation = 0;
    /// The whole image mean's standard error over the seeds, over its size (0 for a black image).
    double relativeStandardError = 0;
};

/// From `images` (one per seed, RGB, `width` × `height`) and `tiles` × `tiles` tiles, on the sum of
/// each pixel's three channels.
SeedSpread seedSpread(const std::vector<std::vector<float>>& images, int width, int height,
                      int tiles);

/// Beyond this, a lab is too noisy to judge. With 10 seeds a correlation ratio is about a
/// chi-square of 9 degrees over 9: above 10 with probability 1e-14 for independent pixels (the
/// reference solutions' ranged 0.2 to 2.2 on the public scenes). The whole image's relative
/// standard error was at most 0.0066 for every reference solution on every public scene at the
/// rubric's samples; 0.1 is 15 times that.
constexpr double MaxCorrelation = 10;
constexpr double MaxRelativeStandardError = 0.1;

/// Whether `spread` is beyond either limit.
bool tooNoisyToJudge(const SeedSpread& spread);

/// The likely cause the grader tells, its name (up to the colon) the diagnosis.
inline constexpr const char* TooNoisyCause =
    "too noisy to judge: a value added to the image that changes with the seed, rare enormous "
    "samples (a weight divided by a tiny probability), or random numbers that are not "
    "ctx.sampler's";

} // namespace pathlab::grader
