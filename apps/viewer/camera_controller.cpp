#include "camera_controller.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace pathlab::viewer {

namespace {
/// Rotates v about the unit axis by angle (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& axis, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}
} // namespace

CameraSettings orbit(const CameraSettings& camera, float dx, float dy) {
    CameraSettings out = camera;
    const Vec3 up = normalize(camera.up);
    Vec3 offset = camera.position - camera.lookAt;
    // A left-handed image is mirrored, and so is the drag that turns it.
    offset = rotate(offset, up, camera.leftHanded ? dx : -dx);
    const Vec3 right = normalize(cross(up, offset));
    const Vec3 tilted = rotate(offset, right, dy);
    // Stop short of the poles, where "up" and the view would line up.
    if (std::fabs(dot(normalize(tilted), up)) < 0.99f) offset = tilted;
    out.position = camera.lookAt + offset;
    return out;
}

CameraSettings move(const CameraSettings& camera, float forward, float right) {
    CameraSettings out = camera;
    const Vec3 view = normalize(camera.lookAt - camera.position);
    // The camera's right, see camera.cpp.
    const Vec3 side = normalize(cross(view, camera.up)) * (camera.leftHanded ? -1.0f : 1.0f);
    const Vec3 step = view * forward + side * right;
    out.position = camera.position + step;
    out.lookAt = camera.lookAt + step;
    return out;
}

std::string cameraAsOptions(const CameraSettings& c) {
    char text[256];
    std::snprintf(text, sizeof text, "-vp %g %g %g -vi %g %g %g -vu %g %g %g -fov %g", c.position.x,
                  c.position.y, c.position.z, c.lookAt.x, c.lookAt.y, c.lookAt.z, c.up.x, c.up.y,
                  c.up.z, c.fovDegrees);
    return c.leftHanded ? std::string(text) + " -lefthanded" : std::string(text);
}

} // namespace pathlab::viewer
