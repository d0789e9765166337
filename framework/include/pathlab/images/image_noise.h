#pragma once
/// PathLab's noise figure: how far an image is from what it converges to, relative to its
/// brightness, measured from the image's own samples. The panel, `--stats`, `grader --report`
/// and the handouts' tables all show this one number (handouts/00-setup.md, "The noise figure").

#include "pathlab/color.h"

namespace pathlab {

/// The relative standard error of an image of `spp` samples per pixel:
///
///     noise = sqrt( mean over pixels and channels of s² / spp ) / mean over pixels and channels of
///     L̄
///
/// with s² a pixel's sample variance (per channel) and L̄ its mean. The numerator is the
/// root-mean-square standard error of the pixel values: the RMS error of the image against its
/// expectation, estimated from the samples. Dark pixels and pixels that few paths reach add their
/// variance like any other and are never divided by their own small mean, so the figure does not
/// depend on which pixels happen to be reached yet. For an estimator of finite variance it halves
/// when the samples quadruple; for one of infinite variance (lab 4 at a low continueProb) it
/// does not settle.
///
/// `meanVariance` and `meanRadiance` are the per-channel means over the pixels, as `--stats`
/// writes them (`mean_variance`, `mean_radiance`). 0 for a black image or fewer than 2 spp.
double imageNoise(const Color& meanVariance, const Color& meanRadiance, int spp);

/// Efficiency 1/(noise² · seconds): for an estimator of finite variance it does not depend on how
/// long the render ran (noise² falls as 1/seconds), so it compares estimators at equal time. A
/// noise of 0.01 takes 10⁴ / efficiency seconds at the same image size. 0 when undefined.
double renderEfficiency(double noise, double seconds);

} // namespace pathlab
