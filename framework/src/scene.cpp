#include "pathlab/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pathlab {

CameraSettings Scene::framingCamera() const {
    constexpr float inf = std::numeric_limits<float>::infinity();
    Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
    for (const Vec3& p : positions) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    CameraSettings camera;
    const Vec3 centre = (lo + hi) * 0.5f;
    const float radius = 0.5f * length(hi - lo);
    camera.fovDegrees = 45.0f;
    // Far enough back that a sphere around the bounding box fits the 45° view.
    camera.position = centre - Vec3{0, 0, radius / std::tan(0.5f * 45.0f * 3.14159265f / 180.0f)};
    camera.lookAt = centre;
    return camera;
}

} // namespace pathlab
