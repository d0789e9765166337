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

/// The unit direction from `scene`'s model towards a camera PathLab places: framingDirection(),
/// unless the model shows less than a third of the area from there that it shows face-on (its largest
/// triangle's normal) or along an axis: then the best of those, so that a flat model (a floor,
/// one triangle) is not seen edge-on. Never straight along `up`, where the camera has no sides.
Vec3 framingDirectionFor(const Scene& scene, const Vec3& up);

/// The share of the image's narrower half-extent the framed model reaches: a margin of 5%.
constexpr float FramingFill = 0.95f;

/// `given` completed where it lacks a position or a look-at point, for a model made of the
/// vertices of `scene`'s triangles. With neither, the camera looks along framingDirectionFor() at
/// the model, centred on it as seen from there, just far enough back that every vertex is in
/// the image of `aspect` (width / height) and one reaches FramingFill of it: a flat or long
/// model fills the image as a round one does. With the look-at point alone, it stands back from
/// that point along framingDirectionFor() (or against --vd) just as far; with the position alone,
/// it looks at the centre of the model's box. The up vector is kept.
CameraSettings framingCamera(const Scene& scene, const GivenCamera& given, float aspect);

/// Whether next-event estimation has a light to sample: a triangle whose material emits
/// (Ke > 0), a point light or a directional light.
bool hasLight(const Scene& scene);

/// A point light at the camera (a headlight: whatever the camera sees is lit), of intensity
/// I = π·d² per channel, d the look-at distance, so that a white (Kd 1) surface facing the
/// camera there has irradiance I/d² = π and radiance Kd/π·π = 1.
PointLight headlight(const CameraSettings& camera);

} // namespace pathlab
