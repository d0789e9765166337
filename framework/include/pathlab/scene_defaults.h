#pragma once
/// What PathLab supplies when a scene lacks it, so that an OBJ given alone renders the model
/// rather than black: a camera that frames it, and a point light at that camera.

#include "pathlab/bounding_box.h"
#include "pathlab/camera.h"
#include "pathlab/scene.h"

#include <optional>

namespace pathlab {

/// The camera options given: their values, and which of those that place the camera were given.
struct GivenCamera {
    CameraSettings settings;
    bool position = false; ///< --vp
    bool lookAt = false;   ///< --vi or --vd
    bool fov = false;      ///< --fov
    /// --vd without --vp: the camera looks along it, at the model, rather than from
    /// framingDirection().
    std::optional<Vec3> viewDirection;
};

/// The field of view of a camera PathLab places, unless --fov gave one.
constexpr float FramingFovDegrees = 45.0f;

/// The unit direction from the model towards a camera PathLab places: the front (+z, the usual
/// OBJ convention with +y up, which Blender's OBJ export writes), a little above and to the side.
Vec3 framingDirection();

/// `given` completed where it lacks a position or a look-at point. With neither, the camera
/// looks at the centre of `bounds` from framingDirection(), just far enough that the sphere
/// around the box fits the vertical field of view and the image's `aspect` (width / height);
/// with the position alone, it looks at the centre; with the look-at point alone, it stands
/// that distance from it along framingDirection(). The up vector is kept.
CameraSettings framingCamera(const BoundingBox& bounds, const GivenCamera& given, float aspect);

/// Whether next-event estimation has a light to sample: a triangle whose material emits
/// (Ke > 0), a point light or a directional light.
bool hasLight(const Scene& scene);

/// A point light at the camera (a headlight: whatever the camera sees is lit), of intensity
/// I = π·d² per channel, d the look-at distance, so that a white (Kd 1) surface facing the
/// camera there has irradiance I/d² = π and radiance Kd/π·π = 1.
PointLight headlight(const CameraSettings& camera);

} // namespace pathlab
