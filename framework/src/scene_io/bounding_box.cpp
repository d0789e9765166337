#include "pathlab/scene_io/bounding_box.h"

#include <algorithm>
#include <limits>

namespace pathlab {

BoundingBox boundingBoxOf(const std::vector<Vec3>& positions) {
    if (positions.empty()) return {{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}};
    constexpr float inf = std::numeric_limits<float>::infinity();
    BoundingBox box{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const Vec3& p : positions) {
        box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
        box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
    }
    return box;
}

} // namespace pathlab
