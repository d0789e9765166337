#pragma once
/// How far an image is from a reference, as rendering papers measure it: relMSE, and the relative
/// RMSE. viewer -o ... --reference prints both and --stats writes them.

#include <vector>

namespace pathlab {

/// The ε of relMSE: it keeps black reference pixels from dividing by zero. 1e-2, as Rousselle et
/// al. (2011) and Mitsuba use it, for radiance of the order of 1.
constexpr double relMseEpsilon = 1e-2;

/// One value's relative squared error (x − r)² / (r² + ε).
inline double relativeSquaredError(float x, float r, double epsilon = relMseEpsilon) {
    const double d = static_cast<double>(x) - r;
    return d * d / (static_cast<double>(r) * r + epsilon);
}

/// relMSE: the mean over pixels and channels of (x − r)² / (r² + ε). 0 for an image equal to its
/// reference. `image` and `reference` are linear RGB of the same size.
double relativeMse(const std::vector<float>& image, const std::vector<float>& reference,
                   double epsilon = relMseEpsilon);

/// The relative RMSE: the root of the mean over pixels and channels of (x − r)², divided by the
/// mean of the reference over pixels and channels (no ε: bright pixels weigh more than in relMSE).
/// 0 when the reference is black.
double relativeRmse(const std::vector<float>& image, const std::vector<float>& reference);

} // namespace pathlab
