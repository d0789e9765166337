#pragma once
/// Where an image is noisy: each pixel's relative standard error, from the accumulation buffer's
/// own samples (no reference needed). viewer --noise-image and the window's noise view show it.

#include <vector>

namespace pathlab {

/// Per pixel sqrt( mean over channels of s²/spp / (L̄² + ε) ), with s² the pixel's sample
/// variance and L̄ its mean per channel, ε relMseEpsilon (pathlab/images/relative_mse.h). Its square
/// is the relative squared error the pixel is expected to have against the converged image (what
/// --error-image measures against a reference), so the two maps read alike; ε keeps dark pixels
/// from dividing by their own small mean, as relMSE does. `mean` and `variance` are linear RGB,
/// one triple per pixel (AccumulationBuffer::meanImage, varianceImage); 0 everywhere below 2 spp.
std::vector<float> relativeStandardErrorMap(const std::vector<float>& mean,
                                            const std::vector<float>& variance, int spp);

} // namespace pathlab
