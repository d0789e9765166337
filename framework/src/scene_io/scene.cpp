#include "pathlab/scene_io/scene.h"

#include "pathlab/scene_io/scene_defaults.h"

#include <algorithm>

namespace pathlab {

BoundingBox Scene::bounds() const {
    if (triangles.empty()) return boundingBoxOf({});
    // Grown vertex by vertex rather than from a copy of the used vertices: a model of a million
    // triangles would copy 36 MB to learn six numbers.
    const Vec3& first = positions[triangles[0][0]];
    BoundingBox box{first, first};
    for (const auto& triangle : triangles) {
        for (const uint32_t v : triangle) {
            const Vec3& p = positions[v];
            box.lo = {std::min(box.lo.x, p.x), std::min(box.lo.y, p.y), std::min(box.lo.z, p.z)};
            box.hi = {std::max(box.hi.x, p.x), std::max(box.hi.y, p.y), std::max(box.hi.z, p.z)};
        }
    }
    return box;
}

CameraSettings Scene::framingCamera() const {
    return pathlab::framingCamera(*this, GivenCamera{}, 1.0f);
}

} // namespace pathlab
