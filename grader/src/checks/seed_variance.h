#pragma once
/// The noise check's statistic: how noisy one sample of a lab is, measured from the images of
/// independent seeds alone, robustly. It is not the noise figure students read off the panel
/// (pathlab/images/image_noise.h). The grader takes nothing from a lab's process but its images,
/// never the figures it reports about itself, so it measures the variance from the spread of
/// independent seeds' images; and it decides a verdict between two labs, which one rare firefly
/// must not decide.

#include <vector>

namespace pathlab::grader {

/// The share of pixels, the noisiest, that the figure leaves out.
constexpr double NoiseTrimmedShare = 0.01;

/// The per-sample variance of a render, from `images` (k ≥ 2 renders of the same scene and
/// spp, with independent seeds; linear RGB): for each pixel, the variance of its k values times
/// spp, averaged over the channels; then the mean over the pixels but the noisiest 1%.
///
/// Why trimmed: the variance of these estimators has heavy tails (a rare path through the glass
/// sphere with a large weight), so the plain mean over pixels is now and then decided by one
/// firefly in one pixel: a correct lab failed the check that way once in about 70 gradings. A
/// bug that makes a lab noisier (a uniform pick where an importance pick belongs) raises the
/// variance of most pixels, and the trimmed mean sees it as clearly as the plain one.
double trimmedSampleVariance(const std::vector<std::vector<float>>& images, int spp);

} // namespace pathlab::grader
