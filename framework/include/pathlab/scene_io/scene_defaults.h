#pragma once
/// What PathLab supplies when a scene lacks it, so that an OBJ given alone renders the model
/// rather than black: a camera that frames it, and a point light at that camera.

#include "pathlab/scene_io/bounding_box.h"
#include "pathlab/scene_io/camera.h"
#include "pathlab/scene_io/scene.h"

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

/// A view that fills this share of the image is good enough: the usual direction is kept.
constexpr double FramingEnoughShare = 0.15;
/// Below that, another direction is taken only when the model fills this many times as much of
/// the image from there: a model is seen from the front unless that shows it poorly.
constexpr double FramingBetterBy = 1.5;
/// ... and only from where no vertex is nearer than this many times the model's radius.
constexpr float FramingLeastNearDistance = 0.75f;

/// The unit direction from `scene`'s model towards a camera PathLab places (`camera`'s up
/// vector and field of view, looking at its lookAt if `lookAtGiven`): framingDirection(),
/// unless the model fills less than FramingEnoughShare of the image from there
/// (model_coverage.h) and FramingBetterBy times as much from its largest face's normal or from
/// one of the 26 directions of the cube around it: then the best of those. So a flat model is
/// not seen edge-on, nor a thin one end-on.
Vec3 framingDirectionFor(const Scene& scene, const CameraSettings& camera, bool lookAtGiven,
                         float aspect);

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
