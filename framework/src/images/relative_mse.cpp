#include "pathlab/images/relative_mse.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

double relativeMse(const std::vector<float>& image, const std::vector<float>& reference,
                   double epsilon) {
    const size_t values = std::min(image.size(), reference.size());
    if (values == 0) return 0;
    double sum = 0;
    for (size_t i = 0; i < values; ++i)
        sum += relativeSquaredError(image[i], reference[i], epsilon);
    return sum / static_cast<double>(values);
}

double relativeRmse(const std::vector<float>& image, const std::vector<float>& reference) {
    const size_t values = std::min(image.size(), reference.size());
    if (values == 0) return 0;
    double squares = 0, referenceSum = 0;
    for (size_t i = 0; i < values; ++i) {
        const double d = static_cast<double>(image[i]) - reference[i];
        squares += d * d;
        referenceSum += reference[i];
    }
    const double referenceMean = referenceSum / static_cast<double>(values);
    return referenceMean > 0 ? std::sqrt(squares / static_cast<double>(values)) / referenceMean : 0;
}

} // namespace pathlab
