#pragma once
/// Mouse-drag orbit and WASD/arrow-key movement of the camera, as in Embree's tutorials.

#include "pathlab/scene_io/camera.h"

#include <string>

namespace pathlab::viewer {

/// Turns the camera around the point it looks at: `dx`, `dy` in radians (drag right turns the
/// view right, drag up tilts it up).
CameraSettings orbit(const CameraSettings& camera, float dx, float dy);

/// Moves eye and look-at point together: `forward` along the view, `right` across it, in scene
/// units.
CameraSettings move(const CameraSettings& camera, float forward, float right);

/// The camera as .ecs options: "-vp x y z -vi x y z -vu x y z -fov f".
std::string cameraAsOptions(const CameraSettings& camera);

} // namespace pathlab::viewer
