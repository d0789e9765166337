#pragma once
/// How much of an image a model fills, seen by a camera: a coarse raster of its triangles, for
/// choosing where a camera PathLab places looks from (scene_defaults.h).

#include "pathlab/scene_io/camera.h"
#include "pathlab/scene_io/scene.h"

namespace pathlab {

/// The share (0 to 1) of the pixels of an image `columns` wide, of `aspect` width / height,
/// through whose centre `camera` sees the front side of a triangle of `scene` (its vertices
/// counter-clockwise) as the nearest surface: a room whose walls face inward counts from its
/// open side, not from behind its walls. A triangle smaller than a pixel marks the pixel its
/// first vertex falls in, so a fine mesh counts as what it covers. Triangles reaching behind
/// the camera are left out. Above a few hundred thousand triangles an even sample of them is
/// drawn, which covers nearly what all do.
double coveredShare(const Scene& scene, const CameraSettings& camera, float aspect,
                    int columns = 48);

} // namespace pathlab
