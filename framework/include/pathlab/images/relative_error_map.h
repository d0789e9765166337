#pragma once
/// Where an image is far from its reference: each pixel's relative squared error, whose mean over
/// the pixels is relMSE (pathlab/images/relative_mse.h). viewer --error-image writes it.

#include <vector>

namespace pathlab {

/// Per pixel the mean over its three channels of (x − r)² / (r² + ε), row-major like the images;
/// one value per pixel. `image` and `reference` are linear RGB of the same size.
std::vector<float> relativeErrorMap(const std::vector<float>& image,
                                    const std::vector<float>& reference);

} // namespace pathlab
