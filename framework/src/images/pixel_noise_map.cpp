#include "pathlab/images/pixel_noise_map.h"

#include "pathlab/images/relative_mse.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

std::vector<float> relativeStandardErrorMap(const std::vector<float>& mean,
                                            const std::vector<float>& variance, int spp) {
    const size_t pixels = std::min(mean.size(), variance.size()) / 3;
    std::vector<float> map(pixels, 0.0f);
    if (spp < 2) return map;
    for (size_t i = 0; i < pixels; ++i) {
        double relativeVariance = 0;
        for (size_t c = 0; c < 3; ++c) {
            const double m = mean[3 * i + c];
            relativeVariance += variance[3 * i + c] / spp / (m * m + relMseEpsilon);
        }
        map[i] = static_cast<float>(std::sqrt(relativeVariance / 3));
    }
    return map;
}

} // namespace pathlab
