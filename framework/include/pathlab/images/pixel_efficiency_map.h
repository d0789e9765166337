#pragma once
/// Where samples pay off: each pixel's efficiency, the per-pixel counterpart of the panel's
/// efficiency figure (pathlab/images/image_noise.h). The window's efficiency view shows it.

#include <vector>

namespace pathlab {

/// Per pixel 1 / (relative variance × seconds per sample): the relative variance of one sample,
/// s² / (L̄² + ε) channel-averaged (the square of relativeStandardErrorMap times spp), times the
/// seconds one sample per pixel cost (the render's seconds / spp; the renderer does not time
/// pixels one by one, so every pixel is charged the image's average). Equivalently
/// 1 / (relative standard error² × seconds): like renderEfficiency it does not change as the
/// samples add up, for an estimator of finite variance, and 1/efficiency is the seconds to a
/// relative standard error of 1 in that pixel. `relativeStandardError` is
/// relativeStandardErrorMap's; a pixel with none (no noise: black, or light straight from a lamp)
/// gets 0, which means undefined, as does every pixel when `seconds` is not positive.
std::vector<float> efficiencyMap(const std::vector<float>& relativeStandardError, double seconds);

} // namespace pathlab
