#include "checks/seed_variance.h"

#include <algorithm>

namespace pathlab::grader {

double trimmedSampleVariance(const std::vector<std::vector<float>>& images, int spp) {
    if (images.size() < 2 || images.front().empty()) return 0;
    const size_t values = images.front().size(), pixels = values / 3;
    const double k = static_cast<double>(images.size());
    std::vector<double> perPixel(pixels, 0.0);
    for (size_t i = 0; i < values; ++i) {
        double sum = 0, squares = 0;
        for (const std::vector<float>& image : images) {
            sum += image[i];
            squares += static_cast<double>(image[i]) * image[i];
        }
        const double mean = sum / k;
        const double variance = std::max(0.0, (squares / k - mean * mean) * k / (k - 1));
        perPixel[i / 3] += variance * spp / 3;
    }
    const size_t kept =
        std::max<size_t>(1, pixels - static_cast<size_t>(pixels * NoiseTrimmedShare));
    std::nth_element(perPixel.begin(), perPixel.begin() + static_cast<std::ptrdiff_t>(kept - 1),
                     perPixel.end());
    double total = 0;
    for (size_t i = 0; i < kept; ++i) total += perPixel[i];
    return total / static_cast<double>(kept);
}

} // namespace pathlab::grader
