#pragma once
/// The inspected pixel's paths drawn over the image: each vertex projected with the window's
/// camera (the render's, so the paths stay on the surfaces as the camera moves), each segment
/// coloured by the kind of ray it was, shadow rays dashed.

#include "pathlab/scene_io/camera.h"
#include "pathlab/inspect/inspected_path.h"

#include <imgui.h>

#include <optional>
#include <string>

namespace pathlab::viewer {

/// Where a point of the scene lands in the image, as pathlab::Camera makes its rays (its
/// inverse): pixels of a width x height image, (0,0) the top-left corner.
class CameraProjection {
public:
    CameraProjection(const CameraSettings& camera, int width, int height);

    /// The segment from `a` to `b`, cut where it passes behind the camera, in pixels; none when
    /// it lies wholly behind.
    std::optional<std::pair<ImVec2, ImVec2>> segment(const Vec3& a, const Vec3& b) const;

private:
    ImVec2 toPixels(const Vec3& point, float depth) const;

    Vec3 eye_, right_, up_, forward_;
    float halfWidth_ = 1, halfHeight_ = 1, width_ = 1, height_ = 1;
    float near_ = 1e-4f; ///< the depth below which a point counts as behind the camera
};

/// The colour of a ray that arrived by `arrivedBy` (camera, diffuse, mirror, specular,
/// refraction, unknown): the legend's.
ImU32 rayColour(const std::string& arrivedBy);
/// The shadow rays' colour (drawn dashed).
ImU32 shadowRayColour();
/// The colour of the vertex where the lab's path first differs from the reference's.
ImU32 divergenceColour();

/// The legend, as ImGui text in the current window; the first difference's mark only where a
/// comparison with the reference can show one.
void drawRayLegend(bool withDivergence);

/// What to draw: the lab's samples of one pixel, one of them selected (drawn over the others,
/// thicker and opaque), and the vertex to mark, if any.
struct OverlayPaths {
    const PixelInspection* inspection = nullptr;
    size_t selectedSample = 0;
    int markedVertex = -1; ///< a vertex of the selected sample; -1: none
};

/// Draws the paths into `draw` (the background list: under the panels, over the image).
/// `pixelsToScreen` turns image pixels into ImGui's coordinates (the framebuffer scale).
void drawPathOverlay(ImDrawList* draw, const OverlayPaths& paths,
                     const CameraProjection& projection, float pixelsToScreen);

} // namespace pathlab::viewer
