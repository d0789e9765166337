#pragma once
/// `viewer --pick-test`: the pick test (pathlab/inspect/pick_test.h) of the chosen lab, on paths
/// replayed over a grid of the image's pixels.

#include "pathlab/inspect/pick_test.h"
#include "pathlab/render/render_options.h"

namespace pathlab {

class RenderScene;

/// Pixels per side of the grid replayed, and samples per pixel: about 16000 paths, enough for
/// a few hundred visits to each of the VI2 box's materials, in a second or two.
constexpr int PickTestGrid = 32;
constexpr int PickTestSamples = 16;

/// Replays PickTestSamples samples of each pixel of a PickTestGrid × PickTestGrid grid spread
/// over the image through the options' lab and implementation, and tests its picks.
PickTestResult runPickTest(const RenderOptions& options, const RenderScene& scene);

} // namespace pathlab
