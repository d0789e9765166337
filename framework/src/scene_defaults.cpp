#include "pathlab/scene_defaults.h"

#include "pathlab/constants.h"

#include <algorithm>
#include <cmath>

namespace pathlab {

Vec3 framingDirection() { return normalize(Vec3{0.5f, 0.35f, 1.0f}); }

CameraSettings framingCamera(const BoundingBox& bounds, const GivenCamera& given, float aspect) {
    CameraSettings camera = given.settings;
    if (!given.fov) camera.fovDegrees = FramingFovDegrees;
    // The sphere fits a cone of half-angle θ from distance r / sin θ; θ is the narrower of the
    // vertical and horizontal half-angles.
    const float halfVertical = 0.5f * camera.fovDegrees * Pi / 180.0f;
    const float halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const float radius = bounds.radius() > 0 ? bounds.radius() : 1.0f;
    const float distance = radius / std::sin(std::min(halfVertical, halfHorizontal));
    const Vec3 towardCamera =
        given.viewDirection ? -normalize(*given.viewDirection) : framingDirection();
    if (!given.lookAt) camera.lookAt = bounds.centre();
    if (!given.position) camera.position = camera.lookAt + towardCamera * distance;
    // A position given at the centre itself would look nowhere: look past it instead.
    if (length(camera.lookAt - camera.position) == 0)
        camera.lookAt = camera.position - towardCamera;
    return camera;
}

bool hasLight(const Scene& scene) {
    if (!scene.pointLights.empty() || !scene.directionalLights.empty()) return true;
    return std::any_of(scene.triangleMaterials.begin(), scene.triangleMaterials.end(),
                       [&](uint32_t m) { return !isBlack(scene.materials[m].Ke); });
}

PointLight headlight(const CameraSettings& camera) {
    const Vec3 toLookAt = camera.lookAt - camera.position;
    const float intensity = Pi * dot(toLookAt, toLookAt);
    return {camera.position, {intensity, intensity, intensity}};
}

} // namespace pathlab
