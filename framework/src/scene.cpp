#include "pathlab/scene.h"

#include "pathlab/scene_defaults.h"

namespace pathlab {

BoundingBox Scene::bounds() const {
    std::vector<Vec3> used;
    used.reserve(3 * triangles.size());
    for (const auto& triangle : triangles)
        for (const uint32_t v : triangle) used.push_back(positions[v]);
    return boundingBoxOf(used);
}

CameraSettings Scene::framingCamera() const {
    return pathlab::framingCamera(*this, GivenCamera{}, 1.0f);
}

} // namespace pathlab
