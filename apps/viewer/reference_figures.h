#pragma once
/// A headless render against --reference: the reference read and checked before rendering, the
/// figures after.

#include "pathlab/images/image_io.h"
#include "pathlab/render/render_stats.h"

#include <string>
#include <vector>

namespace pathlab::viewer {

/// The reference, read; throws InputError naming --reference when it cannot be read or is not
/// `width` × `height`.
Image readReferenceOfSize(const std::string& path, int width, int height);

/// relMSE and the relative RMSE of `image` against `reference` (pathlab/images/relative_mse.h).
ReferenceFigures compareWithReference(const std::string& file, const std::vector<float>& image,
                                      const Image& reference);

/// "  against ref.exr: relMSE 0.00123 (epsilon 0.01), relative RMSE 0.0456", the line viewer -o
/// prints.
std::string referenceLine(const ReferenceFigures& figures);

} // namespace pathlab::viewer
