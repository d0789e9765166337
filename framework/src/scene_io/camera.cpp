#include "pathlab/scene_io/camera.h"

#include "pathlab/constants.h"

#include <cmath>

namespace pathlab {

Camera::Camera(const CameraSettings& settings, int width, int height) : settings_(settings) {
    forward_ = normalize(settings.lookAt - settings.position);
    // cross(forward, up) rather than cross(up, forward): with +y up and +z forward, +x lands on
    // the image's left, which is how Embree's tutorials (and its cornell_box.ecs) see the scene.
    right_ = normalize(cross(forward_, settings.up));
    up_ = cross(right_, forward_);
    // Embree's left-handed camera turns its image x axis round, the rest stays (camera.h).
    if (settings.leftHanded) right_ = -right_;
    halfHeight_ = std::tan(0.5f * settings.fovDegrees * Pi / 180.0f);
    halfWidth_ = halfHeight_ * static_cast<float>(width) / static_cast<float>(height);
    invWidth_ = 1.0f / static_cast<float>(width);
    invHeight_ = 1.0f / static_cast<float>(height);
}

} // namespace pathlab
