#include "pathlab/images/relative_error_map.h"

#include "pathlab/images/relative_mse.h"

#include <algorithm>

namespace pathlab {

std::vector<float> relativeErrorMap(const std::vector<float>& image,
                                    const std::vector<float>& reference) {
    const size_t pixels = std::min(image.size(), reference.size()) / 3;
    std::vector<float> map(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        double sum = 0;
        for (size_t c = 0; c < 3; ++c)
            sum += relativeSquaredError(image[3 * i + c], reference[3 * i + c]);
        map[i] = static_cast<float>(sum / 3);
    }
    return map;
}

} // namespace pathlab
