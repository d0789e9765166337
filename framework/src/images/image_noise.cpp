#include "pathlab/images/image_noise.h"

#include <cmath>

namespace pathlab {

double imageNoise(const Color& meanVariance, const Color& meanRadiance, int spp) {
    const double radiance =
        (static_cast<double>(meanRadiance.r) + meanRadiance.g + meanRadiance.b) / 3;
    const double variance =
        (static_cast<double>(meanVariance.r) + meanVariance.g + meanVariance.b) / 3;
    if (spp < 2 || !(radiance > 0)) return 0;
    return std::sqrt(variance / spp) / radiance;
}

double renderEfficiency(double noise, double seconds) {
    return noise > 0 && seconds > 0 ? 1.0 / (noise * noise * seconds) : 0;
}

} // namespace pathlab
