#include "pathlab/images/pixel_efficiency_map.h"

#include <cstddef>

namespace pathlab {

std::vector<float> efficiencyMap(const std::vector<float>& relativeStandardError, double seconds) {
    std::vector<float> map(relativeStandardError.size(), 0.0f);
    if (!(seconds > 0)) return map;
    for (size_t i = 0; i < map.size(); ++i) {
        const double e = relativeStandardError[i];
        if (e > 0) map[i] = static_cast<float>(1.0 / (e * e * seconds));
    }
    return map;
}

} // namespace pathlab
