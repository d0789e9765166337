#pragma once
/// `viewer --inspect X Y`: a pixel's samples through the chosen lab and, where the build has the
/// reference solutions and the lab is the student's, through the reference on the same random
/// numbers, compared.

#include "pathlab/inspect/inspected_path.h"
#include "pathlab/inspect/path_comparison.h"
#include "pathlab/render/render_options.h"

#include <optional>
#include <vector>

namespace pathlab {

class Camera;
class RenderScene;

struct PixelReplay {
    PixelInspection lab;
    std::optional<PixelInspection> reference; ///< none without the reference solutions
    std::optional<PathComparison> comparison;
};

/// Throws InputError, naming the option, for an --inspect the render cannot do (a pixel
/// outside the image, --inspect-samples or --inspect-out without --inspect): before any render.
void checkInspectOptions(const RenderOptions& options);

struct ReplayedPixel {
    int x = 0, y = 0;
};

/// Each pixel's first `samples` samples replayed through `implementation`'s code of the options'
/// lab, watched for an endless loop as a render is (--watchdog), one inspection per pixel.
std::vector<PixelInspection> inspectLab(const RenderOptions& options, const RenderScene& scene,
                                        const Camera& camera, Implementation implementation,
                                        const std::vector<ReplayedPixel>& pixels, int samples);

PixelReplay replayPixel(const RenderOptions& options, const RenderScene& scene);
/// The same through another camera than the scene's: the window's, once it has moved.
PixelReplay replayPixel(const RenderOptions& options, const RenderScene& scene,
                        const CameraSettings& camera);

/// What `viewer --inspect` prints: the tables (without --inspect-out) and the comparison.
std::string pixelReplayText(const PixelReplay& replay, bool withTables);

} // namespace pathlab
