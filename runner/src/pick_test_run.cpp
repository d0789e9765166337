#include "runner/pick_test_run.h"

#include "runner/pixel_replay.h"

#include "pathlab/render/render_scene.h"
#include "pathlab/scene_io/camera.h"

#include <algorithm>

namespace pathlab {

PickTestResult runPickTest(const RenderOptions& options, const RenderScene& scene) {
    const Camera camera(scene.scene().camera.value_or(scene.scene().framingCamera()), options.width,
                        options.height);
    std::vector<ReplayedPixel> pixels;
    const int columns = std::min(PickTestGrid, options.width);
    const int rows = std::min(PickTestGrid, options.height);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) // each grid cell's centre pixel
            pixels.push_back({(2 * column + 1) * options.width / (2 * columns),
                              (2 * row + 1) * options.height / (2 * rows)});
    return testPicks(
        inspectLab(options, scene, camera, options.implementation, pixels, PickTestSamples));
}

} // namespace pathlab
