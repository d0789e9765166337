#pragma once
/// A pinhole camera set up as Embree's tutorials do (--vp, --vi, --vu, --fov).

#include "pathlab/ray.h"
#include "pathlab/vec3.h"

namespace pathlab {

/// Where the camera is and what it looks at, as the scene script or command line says.
struct CameraSettings {
    Vec3 position{0, 0, -1};  ///< --vp: the eye
    Vec3 lookAt{0, 0, 0};     ///< --vi: a point the camera looks at
    Vec3 up{0, 1, 0};         ///< --vu: roughly up in the image
    float fovDegrees = 90.0f; ///< --fov: vertical field of view
    /// --lefthanded: the image mirrored left-right, +x on its right when looking down +z with +y
    /// up. Embree's tutorials are right-handed unless told (--righthanded is their default).
    bool leftHanded = false;
};

/// Turns image positions into primary rays. Right-handed unless the settings say left-handed:
/// looking down +z with +y up puts +x on the left of the image, as Embree's tutorials do.
class Camera {
public:
    Camera(const CameraSettings& settings, int width, int height);

    /// The ray through image position (x, y) in pixels, (0,0) the top-left corner. Inline: the
    /// renderer makes one per sample.
    Ray generateRay(float x, float y) const {
        const float sx = (2.0f * x * invWidth_ - 1.0f) * halfWidth_;
        const float sy = (1.0f - 2.0f * y * invHeight_) * halfHeight_;
        return {settings_.position, normalize(forward_ + right_ * sx + up_ * sy), RayKind::Camera};
    }

    const CameraSettings& settings() const { return settings_; }

private:
    CameraSettings settings_;
    Vec3 right_, up_, forward_; // orthonormal, in world space
    float halfHeight_ = 1, halfWidth_ = 1;
    float invWidth_ = 1, invHeight_ = 1;
};

} // namespace pathlab
